// Fetching rows read at random ahead of their use. A prefetch into L1 holds
// one of the core's few L1 miss buffers until its line arrives, which caps the
// rows in flight at about a dozen and a half; a prefetch into L2 does not, so
// with enough rows ahead the reads of a random gather overlap many more DRAM
// latencies (refreshing 1M pose rows in a kept frame: 12.4 ns per row
// prefetched 16 ahead into L1, 12.4 at 32 ahead, 7.7-8.6 into L2 at 32 to 96
// ahead). Internal to the library.
#pragma once

#include <cstddef>

namespace obbsat::detail {

/// How many rows ahead a random gather asks for its rows.
constexpr std::size_t random_rows_ahead = 64;

/// Asks for the cache line holding `p` to be brought into L2.
inline void fetch_into_l2(const void* p) { __builtin_prefetch(p, 0, 1); }

}  // namespace obbsat::detail
