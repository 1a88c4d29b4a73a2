// A sort of a few pairs by (a, b) whose cost follows the pairs, not the
// rows they index. The sort of a query's answer (sort/pair_sort.hpp) spreads
// pairs over buckets of a's high bits and counts a digit of each bucket, a
// cost that follows the rows; this one costs passes over the pairs and one
// small count table a pass. Its caller: the few thousand kept pairs a
// pair_finder call with changed rows adds or moves among a hundred thousand
// rows (scene/kept_changes.cpp). Internal to the library.
#pragma once

#include "sort/pair_sort.hpp"

#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Working memory of sort_few_pairs, kept between calls.
struct few_pairs_sort_scratch {
    std::vector<tagged_pair> spare;
    std::vector<std::uint32_t> counts;
};

/// Sorts `pairs` by a then b (equal pairs in no particular order): stable
/// counting sorts of the key a * 2^(bits of the largest b) + b, from its
/// lowest digit up, 12 bits a pass, as many passes as the largest key needs,
/// every pass's counts taken in one read of the pairs.
void sort_few_pairs(std::vector<tagged_pair>& pairs, few_pairs_sort_scratch& scratch);

}  // namespace obbsat::detail
