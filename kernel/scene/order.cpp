// Step 2 of the scene query (pair_search.hpp): the grid of strips and the query's order, sorted anew or repaired.
#include "scene/pair_search.hpp"

#include "scene/search_common.hpp"
#include "sort/radix_sort.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <cstring>
#include <new>
#include <numeric>
#include <vector>

namespace obbsat::detail {

bool pair_search::same_scene_as_last() const {
    return have_order_ && ordered_n_ == n_ && ordered_a_count_ == a_count_ && ordered_kind_ == kind_ &&
           ordered_self_ == self_;
}

void pair_search::order_boxes(const query_input& input, std::size_t parts) {
    // measure_extent computed the keys on the last grid when there was one.
    // A grid made for widened bounds has strips too tall for bounds that
    // are not: a query that widens nothing makes its own.
    const bool keep_grid = same_scene_as_last() && grid_still_fits(grid_, extent_) && !grid_too_wide();
    if (!keep_grid) {
        grid_ = grid_for(extent_, n_, strip_factor);
        grid_widened_ = kept_.keep && kept_.margin > 0.0f;
    }
    keys_.resize(n_);
    order_.resize(n_);
    // The repair needs this query's keys on the last grid (measure_extent).
    stats_.reused_order = keep_grid && keys_by_id_fresh_ && repair_order(parts);
    // A new order's keys are made by the units of the sort's first pass,
    // each its own slice just before it reads it (radix_sort_indices): no
    // pass of their own, and no wait for every key before the sort starts.
    // The order is the sort's indices, written once the keys are all made.
    if (!stats_.reused_order && !keys_by_id_fresh_) {
        // measure_extent left each box's lo_x and lo_y, widened as the sweep
        // will widen them, in keys_ and order_ (as bits).
        const radix_fill keys_from_corners = [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                float lo_x, lo_y;
                std::memcpy(&lo_x, &keys_[i], sizeof(float));
                std::memcpy(&lo_y, &order_[i], sizeof(float));
                keys_[i] = grid_.key_of(lo_x, lo_y);
            }
        };
        // The records' memory, which copy_records fills next, is the sort's
        // working memory first (16 of its 32 bytes a box): a cold query then
        // maps and clears 16 bytes a box fewer of fresh pages. The words live
        // in that memory until the sort is done; copy_records puts records back.
        // (records_ is aligned to a cache line by its allocator.)
        // A double query that reads no float record (double_records_only) sorts in its double records' memory.
        static_assert(sizeof(record) >= 2 * sizeof(std::uint64_t), "a record holds two words of the sort");
        static_assert(sizeof(record64) >= 2 * sizeof(std::uint64_t), "a record64 holds two words of the sort");
        std::uint64_t* words = nullptr;
        if (double_records_only()) {
            records64_.resize(n_);
            words = reinterpret_cast<std::uint64_t*>(records64_.data());
        } else {
            records_.resize(n_);
            words = reinterpret_cast<std::uint64_t*>(records_.data());
        }
        for (std::size_t w = 0; w < 2 * n_; ++w) {
            ::new (static_cast<void*>(words + w)) std::uint64_t;  // no code: words begin to live here
        }
        radix_sort_indices(keys_.data(), order_.data(), n_, grid_.key_bits(), words, words + n_, parts,
                           keys_from_corners, &sort_buckets_);
    } else if (!stats_.reused_order) {
        const radix_fill keys_from_rows = [&](std::size_t begin, std::size_t end) {
            bounds_run b;
            for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
                const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
                input_bounds(input, run_begin, run_end, b);
                widen(b, run_end - run_begin);
                for (std::size_t i = run_begin; i < run_end; ++i) {
                    keys_[i] = grid_.key_of(b.lo_x[i - run_begin], b.lo_y[i - run_begin]);
                }
            }
        };
        radix_sort_indices(keys_.data(), order_.data(), n_, grid_.key_bits(), packed_, spare_, parts, keys_from_rows,
                           &sort_buckets_);
    }
    have_order_ = true;
    ordered_n_ = n_;
    ordered_a_count_ = a_count_;
    ordered_kind_ = kind_;
    ordered_self_ = self_;
}

bool pair_search::repair_order(std::size_t parts) {
    // The last order with this query's keys: nearly sorted when the
    // rectangles moved a little, but for those that changed strips, each of
    // which an insertion sort would carry across about half its new strip.
    // So the rectangles that stayed in their strips keep the last order and
    // are repaired there, strip by strip, the strips split between the
    // threads; those that changed strips are sorted apart; the two are then
    // merged. keys_ still holds the last query's keys, in its order.
    // Every pass is cut into units taken as they come (work_shares.hpp),
    // the same units in the passes that hand each other counts.
    const unsigned q_bits = grid_.q_bits;
    const std::size_t units = units_for(n_, parts, min_boxes_per_unit);
    changed_strip_.resize(n_);
    std::vector<std::size_t> changed_before(units + 1, 0);
    run_units(units, parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, units);
        std::size_t changed = 0;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t key = key_by_id_[order_[k]];
            const bool moved = (key >> q_bits) != (keys_[k] >> q_bits);
            changed_strip_[k] = moved ? 1 : 0;
            changed += moved ? 1 : 0;
            keys_[k] = key;
        }
        changed_before[share + 1] = changed;
    });
    std::partial_sum(changed_before.begin(), changed_before.end(), changed_before.begin());
    const std::size_t changed = changed_before[units];
    const std::size_t stayed = n_ - changed;
    stay_keys_.resize(stayed);
    stay_ids_.resize(stayed);
    moved_keys_.resize(changed);
    moved_ids_.resize(changed);
    // The rectangles that stayed are in the order of their strips already,
    // as each share checks (and the shares' ends against each other): the
    // strips are found by position below.
    std::vector<std::uint32_t> first_strip(units, 0), last_strip(units, 0);
    std::vector<unsigned char> in_strip_order(units, 1);
    run_units(units, parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, units);
        std::size_t m = changed_before[share];
        std::size_t s = begin - m;
        const std::size_t share_first = s;
        std::uint32_t last = 0;
        unsigned ordered = 1;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t key = keys_[k];
            if (changed_strip_[k] != 0) {
                moved_keys_[m] = key;
                moved_ids_[m] = order_[k];
                ++m;
            } else {
                ordered &= (key >> q_bits) >= last ? 1u : 0u;
                last = key >> q_bits;
                stay_keys_[s] = key;
                stay_ids_[s] = order_[k];
                ++s;
            }
        }
        first_strip[share] = s > share_first ? stay_keys_[share_first] >> q_bits : 0;
        last_strip[share] = last;
        in_strip_order[share] = static_cast<unsigned char>(ordered);
    });
    std::uint32_t last_so_far = 0;
    for (std::size_t share = 0; share < units; ++share) {
        const auto [begin, end] = share_of(n_, share, units);
        const bool stayers = end - begin > changed_before[share + 1] - changed_before[share];
        if (in_strip_order[share] == 0 || (stayers && first_strip[share] < last_so_far)) {
            return false;
        }
        last_so_far = stayers ? last_strip[share] : last_so_far;
    }
    std::vector<std::uint32_t> strip_begin(grid_.strips + 1);
    run_units(units, parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(stayed, share, units);
        bucket_starts(stay_keys_.data(), stayed, q_bits, grid_.strips, begin, end, strip_begin.data());
    });
    std::vector<unsigned char> repaired(units, 1);
    run_units(units, parts, [&](std::size_t share) {
        const std::size_t first = grid_.strips * share / units;
        const std::size_t last = grid_.strips * (share + 1) / units;
        const std::size_t begin = strip_begin[first];
        const std::size_t end = strip_begin[last];
        std::size_t budget = 16 * (end - begin);
        for (std::size_t s = first; s < last && repaired[share] != 0; ++s) {
            const std::size_t b = strip_begin[s];
            const std::size_t count = strip_begin[s + 1] - b;
            std::size_t moved = 0;
            if (!repair_sort(stay_keys_.data() + b, stay_ids_.data() + b, count, budget, &moved)) {
                repaired[share] = 0;
            }
            budget -= std::min(budget, moved);
        }
    });
    if (std::find(repaired.begin(), repaired.end(), 0) != repaired.end()) {
        return false;
    }
    radix_sort(moved_keys_.data(), moved_ids_.data(), changed, grid_.key_bits(), packed_, spare_, parts,
               &sort_buckets_);
    merge_by_key(stay_keys_.data(), stay_ids_.data(), stayed, moved_keys_.data(), moved_ids_.data(), changed,
                 keys_.data(), order_.data(), parts);
    return true;
}

}  // namespace obbsat::detail
