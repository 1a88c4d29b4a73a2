// Sorting a query's pairs by (a, b). One pass scatters the pairs by the high
// bits of a into at most 256 buckets; each bucket, small enough for the
// cache, is then sorted by the low bits of a (a counting sort) and each run
// of equal a (a handful of pairs in a scene) by b. Internal to the library.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Working memory of one thread of sort_pairs, kept between calls.
struct pair_sort_scratch {
    std::vector<pair_index> spare;
    std::vector<std::uint32_t> counts;
};

/// Every pair of every source, sorted by a then b, into `out`; every a must
/// be < a_count. One thread of the shared pool per source scatters it; the
/// buckets are then sorted by scratch.size() threads.
void sort_pairs(const std::vector<const std::vector<pair_index>*>& sources, std::size_t a_count,
                std::vector<pair_index>& out, std::vector<pair_sort_scratch>& scratch);

}  // namespace obbsat::detail
