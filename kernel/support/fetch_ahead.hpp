// Fetching rows read at random ahead of their use. A prefetch into L1 holds
// one of the core's few L1 miss buffers until its line arrives, which caps the
// rows in flight at about a dozen and a half; a prefetch into L2 does not, so
// with enough rows ahead the reads of a random gather overlap many more DRAM
// latencies (refreshing 1M pose rows in a kept frame: 12.4 ns per row
// prefetched 16 ahead into L1, 12.4 at 32 ahead, 7.7-8.6 into L2 at 32 to 96
// ahead). Internal to the library; internal linkage, as everything the
// per-ISA translation units share (kernel/lanes/README.md).
#pragma once

#include <cstddef>

namespace obbsat::detail {
namespace {

/// How many rows ahead a random gather asks for its rows.
constexpr std::size_t random_rows_ahead = 64;

/// Asks for the cache line holding `p` to be brought into L2.
inline void fetch_into_l2(const void* p) { __builtin_prefetch(p, 0, 1); }

/// How a batch over a pair list fetches the records of the pairs ahead.
enum class pair_fetch {
    none,      ///< not at all: the records of a sweep's pairs are neighbours, already on their way
    into_l1,   ///< 16 pairs ahead into L1: a store the caches hold (one read from L3 is short)
    into_l2,   ///< 128 pairs ahead into L2: a store read from DRAM
};

/// How many pairs ahead `Fetch` asks for the records.
template <pair_fetch Fetch>
constexpr std::size_t pairs_ahead = Fetch == pair_fetch::into_l2 ? 128 : 16;

/// Asks for the record at `p` as `Fetch` does.
template <pair_fetch Fetch>
inline void fetch_record(const void* p) {
    if constexpr (Fetch == pair_fetch::into_l1) {
        __builtin_prefetch(p);
    } else if constexpr (Fetch == pair_fetch::into_l2) {
        fetch_into_l2(p);
    }
}

/// A store of at most this many bytes fits in a core's L2: its records are
/// read at random from L2, which the core's own reordering covers, and its
/// pair lists fetch nothing ahead (the prefetches would only cost
/// instructions). Measured on AVX-512, one thread, ns per pair with and
/// without fetching 16 pairs ahead into L1, sorted lists: local 1.63-1.68
/// against 1.45-1.47 at 64 KiB of records, 1.89-1.95 against 1.72 at 2 MiB;
/// sat4 2.85-3.13 against 2.82-2.85 at 64 KiB; at 8 MiB fetching nothing took
/// sat4 7.1-12.4 against 4.4-5.2.
constexpr std::size_t store_bytes_in_l2 = std::size_t{2} << 20;

/// A store of more bytes than this is read from DRAM at random: its pair
/// lists are batched with pair_fetch::into_l2. Measured with local over
/// sorted pair lists (AVX-512): 8 MiB of records 1.76 ns per pair into L1
/// against 1.89 into L2, 16 MiB 2.61 against 2.05, 64 MiB 7.3 against 3.2.
constexpr std::size_t store_bytes_from_dram = std::size_t{12} << 20;

}  // namespace
}  // namespace obbsat::detail
