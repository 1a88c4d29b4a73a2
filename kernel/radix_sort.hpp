// Sorting (key, value) pairs of 32-bit integers by key, stably: a least
// significant digit radix sort over the pairs packed into 64-bit words, 8 bits
// per pass (256 write streams, few enough for the TLB and the store buffers),
// skipping passes whose digit is the same for every key, in memory backed by
// huge pages where the OS offers them. Internal to the library.
#pragma once

#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat::detail {

/// Working memory of radix_sort, kept by the caller between calls.
using radix_buffer = std::vector<std::uint64_t, cache_line_allocator<std::uint64_t>>;

/// Sorts keys[0, n) and values[0, n) together by key, stably; `key_bits` is
/// the number of low bits that can be non-zero. `packed` and `spare` are
/// grown to n. Each pass is split over up to `parts` threads of the shared
/// pool; the result does not depend on how many.
void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, radix_buffer& packed,
                radix_buffer& spare, std::size_t parts = 1);

/// Sorts keys[0, n) and values[0, n) stably by key >> shift, which must be
/// below `buckets`: one counting pass, through `spare_keys` and `spare_values`.
void bucket_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned shift, std::size_t buckets,
                 std::vector<std::uint32_t>& spare_keys, std::vector<std::uint32_t>& spare_values);

/// Sorts keys[0, n) and values[0, n) by key, stably, when they are nearly
/// sorted already: an insertion sort (binary search, then one block move)
/// that gives up (returning false, with the arrays still a permutation of the
/// input) once it would move more than `move_budget` elements.
/// `moved`, when given, receives the elements moved.
bool repair_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, std::size_t move_budget,
                 std::size_t* moved = nullptr);

}  // namespace obbsat::detail
