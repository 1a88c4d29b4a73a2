// The contacts of a scene query's pairs, computed as the pairs are found (query_contacts.hpp).
#include "scene/query_contacts.hpp"

#include <obbsat/error.hpp>

#include <cstdint>
#include <limits>

namespace obbsat::detail {

void query_contacts::read_records(contact_fn kernel, float margin) {
    kernel_ = kernel;
    margin_ = margin;
    rows_ = nullptr;
    stride_ = record_floats;
}

void query_contacts::read_rows(contact_fn kernel, float margin, const float* rows, std::size_t stride) {
    kernel_ = kernel;
    margin_ = margin;
    rows_ = rows;
    stride_ = stride;
}

void query_contacts::start(std::size_t boxes) {
    // About two pairs a box: a large scene fills large blocks.
    block_size_ = boxes >= contact_block::block_contacts ? contact_block::block_contacts
                                                         : contact_block::small_contacts;
    taken_ = 0;
    bases_.clear();
    sorted_.clear();
}

void query_contacts::make_room(unit_contacts& unit, std::size_t count) {
    if (unit.current != nullptr && unit.used + count <= unit.current->contacts.size()) {
        return;
    }
    {
        const std::lock_guard<std::mutex> lock(pool_mutex_);
        // Tags are 32 bits: block number times block_contacts plus a place.
        if (taken_ >= (std::size_t{std::numeric_limits<std::uint32_t>::max()} + 1) / contact_block::block_contacts) {
            throw invalid_input("find_contacts: more than 4294967295 pairs in one query");
        }
        if (taken_ == pool_.size()) {
            pool_.push_back(std::make_unique<contact_block>());
            pool_.back()->number = static_cast<std::uint32_t>(taken_);
        }
        contact_block& block = *pool_[taken_];
        if (block.contacts.size() < block_size_) {
            // Unwritten until the kernel writes (scratch_vector.hpp); huge pages from 4 MiB.
            block.contacts = scratch_records<contact>(block_size_);
            block.pairs = scratch_records<tagged_pair>(block_size_);
        }
        unit.current = &block;
        ++taken_;
    }
    unit.used = 0;
    unit.spans.push_back({unit.current->pairs.data(), 0});
}

void query_contacts::take(unit_contacts& unit, const float* records, const pair_index* candidates,
                          const std::uint8_t* verdicts, std::size_t count, const pair_index* caller,
                          std::size_t kept) {
    if (kept == 0) {
        return;
    }
    make_room(unit, kept);
    contact* const out = unit.current->contacts.data() + unit.used;
    if (rows_ == nullptr) {
        // The colliding candidates, in the query's order, in the order the
        // caller's pairs were written: their records were just tested.
        if (unit.colliding.size() < count) {
            unit.colliding.resize(count);
        }
        pair_index* const colliding = unit.colliding.data();
        std::size_t k = 0;
        for (std::size_t i = 0; i < count; ++i) {
            colliding[k] = candidates[i];
            k += verdicts[i] != 0 ? 1u : 0u;
        }
        kernel_(records, record_floats, records, record_floats, colliding, kept, margin_, out);
    } else {
        kernel_(rows_, stride_, rows_, stride_, caller, kept, margin_, out);
    }
    tagged_pair* const pairs = unit.current->pairs.data() + unit.used;
    const std::size_t first_tag = unit.current->number * contact_block::block_contacts + unit.used;
    for (std::size_t k = 0; k < kept; ++k) {
        pairs[k] = tagged_pair{caller[k].a, caller[k].b, static_cast<std::uint32_t>(first_tag + k)};
    }
    unit.used += kept;
    unit.spans.back().size += kept;
}

void query_contacts::sort(const std::vector<const unit_contacts*>& units, std::size_t groups, std::size_t a_count) {
    bases_.resize(pool_.size());
    for (std::size_t b = 0; b < pool_.size(); ++b) {
        bases_[b] = pool_[b]->contacts.data();
    }
    // The units in unit order, one source per group of threads (sort_pairs
    // scatters one share per source); pairs are unique, so the answer does
    // not depend on the grouping.
    std::vector<pair_source<tagged_pair>> sources(groups);
    for (std::size_t i = 0; i < units.size(); ++i) {
        pair_source<tagged_pair>& into = sources[i * groups / units.size()];
        into.insert(into.end(), units[i]->spans.begin(), units[i]->spans.end());
    }
    if (sort_scratch_.size() < groups) {
        sort_scratch_.resize(groups);
    }
    sorted_.clear();
    sort_pairs(sources, a_count, sorted_, sort_scratch_);
}

}  // namespace obbsat::detail
