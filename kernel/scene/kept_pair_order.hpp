// The sort of the few kept pairs a call with changed rows adds or moves
// (kept_changes.cpp: the new rows' candidates and the pairs of rows that
// changed places), by (a, b). They are a few thousand among a hundred
// thousand rows: the sort of a query's answer (sort/pair_sort.hpp) spreads
// pairs over buckets of a's high bits and counts a digit of each bucket, a
// cost that follows the rows, not the pairs; this one costs passes over the
// pairs and one small count table a pass. Internal to the library.
#pragma once

#include "sort/pair_sort.hpp"

#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Working memory of sort_kept_pairs, kept between calls.
struct kept_pair_order_scratch {
    std::vector<tagged_pair> spare;
    std::vector<std::uint32_t> counts;
};

/// Sorts `pairs` by a then b (equal pairs in no particular order): stable
/// counting sorts of the key a * 2^(bits of the largest b) + b, from its
/// lowest digit up, 11 bits a pass, as many passes as the largest key needs.
void sort_kept_pairs(std::vector<tagged_pair>& pairs, kept_pair_order_scratch& scratch);

}  // namespace obbsat::detail
