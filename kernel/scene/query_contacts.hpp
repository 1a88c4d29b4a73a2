// The contacts a scene query computes while it finds its pairs (find_contacts,
// obbsat/find_contacts.hpp). Internal to the library, baseline ISA.
//
// Why during the query: when the sweep has tested a block of candidates
// (pair_search::flush_candidates), the records of the colliding ones are in
// the cache, in the query's order. The contact kernel run then reads them
// there; run over the sorted answer afterwards, it would read one record at
// random per pair from memory (the caller's order has nothing to do with the
// plane's). So each unit of the sweep hands its colliding pairs here, block
// by block: their contacts go into blocks of a pool kept between queries,
// each pair beside them tagged with where its contact is, and the answer is
// the tagged pairs sorted by (a, b) as find_pairs sorts its pairs, the
// contacts read through the tags.
//
// Two sources of rows:
//   - the query's own records (margin 0: the query runs on the boxes
//     themselves, and its records are their rows, copied verbatim);
//   - the caller's rows, through the pairs in the caller's indices (with a
//     margin the query runs on stand-ins, whose records are not the boxes).
// Either way each contact is the kernel's on the same floats, so bit for bit
// contact_pairs' on the caller's rows.
#pragma once

#include "dispatch/contact_kernel_table.hpp"
#include "sort/pair_sort.hpp"
#include "support/fetch_ahead.hpp"
#include "support/scratch_vector.hpp"

#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace obbsat::detail {

/// Contacts of one block of the pool, and their pairs tagged with where each
/// contact is (block number times block_contacts plus its place). A query of
/// many boxes takes blocks of block_contacts (6 MiB: huge pages, so that
/// neither their first writes nor the sorted answer's reads at random take a
/// page fault or a TLB miss per 4 KiB); a small one takes small_contacts, as
/// each unit writes into a block of its own.
struct contact_block {
    static constexpr std::size_t block_contacts = std::size_t{1} << 17;
    static constexpr std::size_t small_contacts = std::size_t{1} << 13;
    scratch_records<contact> contacts;
    scratch_records<tagged_pair> pairs;
    std::uint32_t number = 0;  ///< its place in the pool
};

/// What one unit of the sweep found: its pairs block by block, in the order found.
struct unit_contacts {
    pair_source<tagged_pair> spans;  ///< one per block it filled
    contact_block* current = nullptr;
    std::size_t used = 0;                ///< contacts in `current`
    std::vector<pair_index> colliding;   ///< working memory: a flush's colliding candidates

    void clear() {
        spans.clear();
        current = nullptr;
        used = 0;
    }
};

class query_contacts {
public:
    /// Contacts of each pair of the query's own records (records of
    /// `record_floats` floats), on the kernel `kernel`, with `margin`.
    void read_records(contact_fn kernel, float margin);
    /// Contacts of each pair read from the caller's rows instead (`rows`,
    /// `stride` floats apart), through the pairs in the caller's indices.
    void read_rows(contact_fn kernel, float margin, const float* rows, std::size_t stride);

    /// Forgets the last query's contacts (the blocks stay for this one) and
    /// sizes the blocks for a query of `boxes` rectangles.
    void start(std::size_t boxes);

    /// Takes the `kept` colliding pairs of one flush: `candidates` (the
    /// query's order, `count` of them, colliding where verdicts[i] != 0,
    /// each the caller's way round) over `records`, and `caller` the same
    /// `kept` pairs in the caller's indices. Called by several units at once.
    void take(unit_contacts& unit, const float* records, const pair_index* candidates, const std::uint8_t* verdicts,
              std::size_t count, const pair_index* caller, std::size_t kept);

    /// The pairs of `units` (in unit order, a group per thread of `groups`),
    /// sorted by (a, b) into `sorted`; every a < a_count.
    void sort(const std::vector<const unit_contacts*>& units, std::size_t groups, std::size_t a_count);

    /// The sorted pairs (after sort) and the contact of each through its tag.
    const std::vector<tagged_pair>& sorted() const { return sorted_; }
    const contact& contact_of(const tagged_pair& p) const {
        return bases_[p.tag / contact_block::block_contacts][p.tag % contact_block::block_contacts];
    }
    /// Fetches the contact of `p` towards the cache ahead of its read; a
    /// contact (48 bytes) may straddle two cache lines.
    void fetch(const tagged_pair& p) const {
        const char* c = reinterpret_cast<const char*>(&contact_of(p));
        fetch_into_l2(c);
        fetch_into_l2(c + sizeof(contact) - 1);
    }

    static constexpr std::size_t record_floats = 8;

private:
    /// A block with room for `count` more contacts for `unit`.
    void make_room(unit_contacts& unit, std::size_t count);

    contact_fn kernel_ = nullptr;
    float margin_ = 0.0f;
    const float* rows_ = nullptr;  ///< nullptr: the query's records
    std::size_t stride_ = record_floats;

    std::mutex pool_mutex_;  ///< guards pool_ and taken_ while units take blocks
    std::vector<std::unique_ptr<contact_block>> pool_;
    std::size_t taken_ = 0;  ///< blocks of the pool this query took
    std::size_t block_size_ = contact_block::small_contacts;  ///< contacts per block in this query
    std::vector<const contact*> bases_;  ///< each block's contacts, for contact_of

    std::vector<tagged_pair> sorted_;
    std::vector<pair_sort_scratch<tagged_pair>> sort_scratch_;
};

}  // namespace obbsat::detail
