// Sorting a query's pairs by (a, b). One pass scatters the pairs by the high
// bits of a into at most 256 buckets; each bucket, small enough for the
// cache, is then sorted by the high bits of b and by the low bits of a (two
// stable counting sorts), and the rare run of equal a left out of order by b
// is sorted on its own. Internal to the library.
#pragma once

#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// A pair with a tag that rides along, such as where it came from.
struct tagged_pair {
    std::uint32_t a;
    std::uint32_t b;
    std::uint32_t tag;
};

/// Working memory of one thread of sort_pairs, kept between calls.
template <class Pair>
struct pair_sort_scratch {
    std::vector<Pair> spare;
    std::vector<std::uint32_t> counts;
};

/// `size` pairs at `data`.
template <class Pair>
struct pair_span {
    const Pair* data;
    std::size_t size;
};

/// The pairs one thread found: its spans, one after the other.
template <class Pair>
using pair_source = std::vector<pair_span<Pair>>;

/// Every pair of every source, sorted by a then b, into `out`; every a must
/// be < a_count. Up to as many threads as there are sources scatter shares of
/// all the pairs, then sort the buckets, both cut into units taken as they
/// come (work_shares.hpp); `scratch` grows to one entry a unit of the
/// buckets. Pair is pair_index or tagged_pair; equal (a, b) keep no
/// particular order.
template <class Pair>
void sort_pairs(const std::vector<pair_source<Pair>>& sources, std::size_t a_count, std::vector<Pair>& out,
                std::vector<pair_sort_scratch<Pair>>& scratch);

}  // namespace obbsat::detail
