// Sorting (key, value) pairs of 32-bit integers by key, stably: a radix sort
// over the pairs packed into 64-bit words, 8 bits per pass (256 write streams,
// few enough for the TLB and the store buffers), skipping passes whose digit
// is the same for every key, in memory backed by huge pages where the OS
// offers them (or lent by the caller). On one thread every digit is counted
// while the keys are packed, and the passes go from the least significant
// digit up; on several, the highest digit that varies splits the keys into
// 256 buckets first, the keys packed as they are scattered, and each bucket
// is then sorted on its own from its least significant digit up, the buckets
// taken as they come by the threads. The values may be the keys' indices
// (radix_sort_indices), which are then never read.
// Internal to the library.
#pragma once

#include "support/scratch_vector.hpp"
#include "support/unit_buffers.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace obbsat::detail {

/// Working memory of radix_sort, kept by the caller between calls.
using radix_buffer = scratch_records<std::uint64_t>;

/// The buffers the buckets of a sort on several threads are sorted in (two
/// words a key of a bucket, up to 16384 keys: 256 KiB each, one a thread),
/// kept by the caller between calls; without them each bucket allocates its own.
using radix_bucket_buffers = unit_buffers<std::uint64_t>;

/// Sorts keys[0, n) and values[0, n) together by key, stably; `key_bits` is
/// the number of low bits that can be non-zero. `packed` and `spare` are
/// grown to n. Each pass is cut into units taken as they come by up to
/// `parts` threads (work_shares.hpp); the result does not depend on how many.
void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, radix_buffer& packed,
                radix_buffer& spare, std::size_t parts = 1, radix_bucket_buffers* buckets = nullptr);

/// radix_sort in working memory the caller lends: `packed` and `spare`, n
/// words each, not overlapping each other, keys or values.
void radix_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, unsigned key_bits, std::uint64_t* packed,
                std::uint64_t* spare, std::size_t parts = 1);

/// Writes keys[begin, end) of a sort to come (radix_sort_indices).
using radix_fill = std::function<void(std::size_t begin, std::size_t end)>;

/// Sorts the indices 0 .. n - 1 by the keys that `fill` writes, stably:
/// afterwards keys[0, n) holds the keys sorted and indices[k] the index of
/// keys[k] before the sort. fill is called over slices that tile [0, n), each
/// slice's keys read just after it is filled, by the same unit of the sort's
/// first pass: making the keys takes no pass of its own and no wait for all
/// of them before the sort starts. `indices` is only written, once every key
/// is filled, so fill may read what it held before.
void radix_sort_indices(std::uint32_t* keys, std::uint32_t* indices, std::size_t n, unsigned key_bits,
                        radix_buffer& packed, radix_buffer& spare, std::size_t parts, const radix_fill& fill,
                        radix_bucket_buffers* buckets = nullptr);

/// radix_sort_indices in working memory the caller lends, as radix_sort's.
void radix_sort_indices(std::uint32_t* keys, std::uint32_t* indices, std::size_t n, unsigned key_bits,
                        std::uint64_t* packed, std::uint64_t* spare, std::size_t parts, const radix_fill& fill,
                        radix_bucket_buffers* buckets = nullptr);

/// Where each bucket begins in keys[0, n), n > 0, sorted by key >> shift
/// (every bucket below `buckets`): starts[b] is the first i whose bucket is
/// at least b, for b in [0, buckets]. A call writes the entries of the
/// buckets that begin in [begin, end) (the last share, end == n, also those
/// after the last key), so calls over shares that tile [0, n) write each
/// entry once and may run at the same time.
void bucket_starts(const std::uint32_t* keys, std::size_t n, unsigned shift, std::size_t buckets, std::size_t begin,
                   std::size_t end, std::uint32_t* starts);

/// Merges a_keys/a_values[0, a_n) and b_keys/b_values[0, b_n), each sorted
/// by key, into out_keys/out_values[0, a_n + b_n), sorted by key; of two
/// equal keys, a's comes first if its value is at most b's, so two runs
/// sorted by (key, value) merge sorted by (key, value). The output overlaps
/// neither run. Shares split by key are units taken as they come by up to
/// `parts` threads (work_shares.hpp; a second thread for at least 16384
/// entries); the result does not depend on how many.
void merge_by_key(const std::uint32_t* a_keys, const std::uint32_t* a_values, std::size_t a_n,
                  const std::uint32_t* b_keys, const std::uint32_t* b_values, std::size_t b_n,
                  std::uint32_t* out_keys, std::uint32_t* out_values, std::size_t parts);

/// Sorts keys[0, n) and values[0, n) by key, stably, when they are nearly
/// sorted already: an insertion sort (binary search, then one block move)
/// that gives up (returning false, with the arrays still a permutation of the
/// input) once it would move more than `move_budget` elements.
/// `moved`, when given, receives the elements moved.
bool repair_sort(std::uint32_t* keys, std::uint32_t* values, std::size_t n, std::size_t move_budget,
                 std::size_t* moved = nullptr);

}  // namespace obbsat::detail
