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

/// Every pair of every source, sorted by a then b, into `out`; every a must
/// be < a_count. `spare` and `counts` are working memory kept between calls.
void sort_pairs(const std::vector<const std::vector<pair_index>*>& sources, std::size_t a_count,
                std::vector<pair_index>& out, std::vector<pair_index>& spare, std::vector<std::uint32_t>& counts);

}  // namespace obbsat::detail
