// Step 3 of the scene query (pair_search.hpp): the visits of rectangles taller than their strip to the strips above.
#include "scene/pair_search.hpp"

#include "scene/search_common.hpp"
#include "sort/radix_sort.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace obbsat::detail {

void pair_search::start_visit_counts(std::size_t units) {
    unit_visits_.assign(units, visit_counts{});
    visits_counted_ = true;
}

void pair_search::count_visits(std::size_t unit, std::size_t begin, std::size_t end) {
    const unsigned q_bits = grid_.q_bits;
    std::size_t near = 0, far = 0;
    for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t low = keys_[k] >> q_bits;
        const std::uint32_t hops = std::max(strip_hi_[k], low) - low;
        const std::uint32_t is_near = hops != 0 ? 1 : 0;
        near += is_near;
        far += hops - is_near;
    }
    unit_visits_[unit] = visit_counts{near, far};
}

void pair_search::collect_visits(std::size_t parts) {
    // A rectangle taller than its strip visits each strip above its lowest
    // up to its highest; the visits are wanted sorted by key, ties by
    // rectangle. The rectangles are in key order, so the visits to the strip
    // just above each one's lowest ("near" visits, most of them) come out in
    // that order already; only the others ("far" visits, of rectangles taller
    // than a strip) are radix sorted, and then merged in. Each unit counts
    // its visits, then writes them after the units before it; the units are
    // taken as they come (work_shares.hpp), and the same in both passes. The
    // count is taken by copy_records' units as they write each rectangle's
    // highest strip: no pass of its own, no wait for every unit between the
    // copy and the count, and strip_hi_ read while it is in the cache.
    //
    // A rectangle's lowest strip (its key) comes from the order's read of the
    // rows, its highest (strip_hi_) from the copy's. Rows the caller changes
    // between the two (forbidden, but possible) may put the highest below the
    // lowest; both passes then take the highest as the lowest (no visit), so
    // that no count underflows and the second pass writes what the first
    // counted.
    const std::uint32_t strips = grid_.strips;
    const unsigned q_bits = grid_.q_bits;
    const std::size_t units = units_for(n_, parts, min_boxes_per_unit);
    // The counts come from copy_records, which takes them over the same
    // units as it writes strip_hi_; a query that did not, counts here.
    if (!visits_counted_ || unit_visits_.size() != units) {
        start_visit_counts(units);
        run_units(units, parts, [&](std::size_t share) {
            const auto [begin, end] = share_of(n_, share, units);
            count_visits(share, begin, end);
        });
    }
    visits_counted_ = false;
    std::vector<std::size_t> first_near(units + 1, 0), first_far(units + 1, 0);
    for (std::size_t share = 0; share < units; ++share) {
        first_near[share + 1] = first_near[share] + unit_visits_[share].near;
        first_far[share + 1] = first_far[share] + unit_visits_[share].far;
    }
    const std::size_t far_count = first_far[units];
    const std::size_t near_count = first_near[units];
    const std::size_t visits = far_count + near_count;
    // One more entry after the last visit, for the sweep's merge to read.
    // With no far visits the near ones are the visits; otherwise they go to
    // arrays of their own, from which the merge reads while it writes.
    visit_keys_.resize(visits + 1);
    visit_ids_.resize(visits + 1);
    far_keys_.resize(far_count);
    far_ids_.resize(far_count);
    if (far_count > 0) {
        near_keys_.resize(near_count);
        near_ids_.resize(near_count);
    }
    std::uint32_t* const near_keys = far_count > 0 ? near_keys_.data() : visit_keys_.data();
    std::uint32_t* const near_ids = far_count > 0 ? near_ids_.data() : visit_ids_.data();
    own_begin_.resize(strips + 1);
    std::vector<unsigned char> near_sorted(units, 1);
    run_units(units, parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, units);
        bucket_starts(keys_.data(), n_, q_bits, strips, begin, end, own_begin_.data());
        std::size_t v = first_near[share];
        const std::size_t v_end = first_near[share + 1];
        std::size_t f = first_far[share];
        std::uint32_t last_key = 0;
        unsigned sorted = 1;
        // Local copies, so that the stores below, which might alias them for
        // all the compiler knows, do not make it read them again each time.
        const std::uint32_t* const keys = keys_.data();
        const std::uint32_t* const highs = strip_hi_.data();
        const std::uint32_t* const q_los = q_lo_.data();
        std::uint32_t* const to_keys = near_keys;
        std::uint32_t* const to_ids = near_ids;
        // Whether a rectangle visits at all is as random as the scene, so
        // every rectangle writes a would-be visit to the next slot, which the
        // next visit overwrites if this was none; after the share's last
        // visit (a well predicted test) they go to `unused`, so that no share
        // writes into the next one's slots.
        std::uint32_t unused[2];
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t low = keys[k] >> q_bits;
            const std::uint32_t high = std::max(highs[k], low);
            const std::uint32_t is_near = high != low ? 1u : 0u;
            const std::uint32_t key = ((low + 1) << q_bits) | q_los[k];
            sorted &= static_cast<unsigned>(key >= last_key) | (is_near ^ 1u);
            last_key = is_near != 0 ? key : last_key;
            const bool room = v < v_end;
            *(room ? to_keys + v : unused) = key;
            *(room ? to_ids + v : unused + 1) = static_cast<std::uint32_t>(k);
            v += is_near;
            for (std::uint32_t s = low + 2; s <= high; ++s) {
                far_keys_[f] = (s << q_bits) | q_los[k];
                far_ids_[f] = static_cast<std::uint32_t>(k);
                ++f;
            }
        }
        near_sorted[share] = static_cast<unsigned char>(sorted);
    });
    // The near visits are in key order when each rectangle's key and its
    // quantized lo_x agree, as they are computed from the same bounds; if
    // they ever did not, every visit is sorted, which gives the same order.
    bool merge = std::find(near_sorted.begin(), near_sorted.end(), 0) == near_sorted.end();
    for (std::size_t share = 1; share < units && merge; ++share) {
        const std::size_t at = first_near[share];
        merge = at == 0 || at == near_count || near_keys[at - 1] <= near_keys[at];
    }
    if (merge) {
        if (far_count > 0) {
            radix_sort(far_keys_.data(), far_ids_.data(), far_count, grid_.key_bits(), packed_, spare_, parts,
                       &sort_buckets_);
            merge_by_key(near_keys_.data(), near_ids_.data(), near_count, far_keys_.data(), far_ids_.data(), far_count,
                         visit_keys_.data(), visit_ids_.data(), parts);
        }
    } else {
        if (far_count > 0) {
            std::copy(far_keys_.begin(), far_keys_.end(), visit_keys_.begin());
            std::copy(far_ids_.begin(), far_ids_.end(), visit_ids_.begin());
            std::copy(near_keys_.begin(), near_keys_.end(), visit_keys_.begin() + static_cast<std::ptrdiff_t>(far_count));
            std::copy(near_ids_.begin(), near_ids_.end(), visit_ids_.begin() + static_cast<std::ptrdiff_t>(far_count));
        }
        radix_sort(visit_keys_.data(), visit_ids_.data(), visits, grid_.key_bits(), packed_, spare_, parts,
                   &sort_buckets_);
    }
    visit_keys_[visits] = 0;
    visit_ids_[visits] = 0;
    visit_begin_.assign(strips + 1, 0);
    if (visits > 0) {
        const std::size_t visit_units = units_for(visits, parts, min_entries_per_unit);
        run_units(visit_units, parts, [&](std::size_t share) {
            const auto [begin, end] = share_of(visits, share, visit_units);
            bucket_starts(visit_keys_.data(), visits, q_bits, strips, begin, end, visit_begin_.data());
        });
    }
    stats_.strips = strips;
    stats_.visits = visits;
}

}  // namespace obbsat::detail
