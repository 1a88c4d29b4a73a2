// Sorting a query's pairs by (a, b): a counting sort on a, then each run of
// equal a (a handful of pairs in a scene) sorted on b. Internal to the library.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Sorts `pairs` by a, then b; every a must be < a_count. `spare` and
/// `counts` are working memory, kept by the caller between calls.
void sort_pairs(std::vector<pair_index>& pairs, std::size_t a_count, std::vector<pair_index>& spare,
                std::vector<std::uint32_t>& counts);

}  // namespace obbsat::detail
