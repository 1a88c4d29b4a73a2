// What several steps of the scene query (pair_search.hpp) share: its block
// sizes and thresholds, and the clock of its stats. Internal to the library,
// baseline ISA; every name has internal linkage or is inline.
#pragma once

#include "scene/pair_blocks.hpp"

#include <chrono>
#include <cstddef>

namespace obbsat::detail {

/// Strips are this many mean bounds heights tall. Taller strips mean fewer
/// visits (a box crosses into the strip above about once in this many) but
/// more entries in reach of each; 3 against 2 took 3-5% less time on the
/// uniform and mixed scenes of 100k and 1M boxes on one thread, exact, and
/// 1.5 more (bench scene/exact/poses/..., alternating binaries).
constexpr double strip_factor = 3.0;

/// Candidates handed to the method's kernel at once.
constexpr std::size_t candidate_block = 2048;
static_assert(candidate_block <= pair_blocks::block_pairs, "a block of candidates fits in a block of found pairs");

/// A query that widens its bounds keeps at most this many times the
/// candidates of the last query, plus one per rectangle; a scene whose
/// widened bounds would give more is answered as a plain query.
constexpr std::size_t kept_budget_factor = 4;

/// A pair_finder whose keeping is paused (kept_pairs::paused) keeps again
/// after this many calls in a row whose bounds all lay inside the last
/// call's bounds widened by the margin a full query would use.
constexpr std::size_t calm_calls_to_resume = 2;
/// The most calls a paused pair_finder lets pass without probing after a failed probe.
constexpr std::size_t max_probe_wait = 16;
/// A paused pair_finder times the order step the other way (repaired or
/// sorted anew) than the cheaper one every this many calls.
constexpr std::size_t order_retime_period = 8;

/// A pair_finder weighs what keeping costs against plain queries
/// (kept_costs.hpp) from this many rows on: a call on fewer takes well under
/// a millisecond, where the clock's noise would choose the path.
constexpr std::size_t min_boxes_weighed = 65536;

/// The most found pairs a part of a streaming query holds, and so hands to
/// the sink at once (find_pairs.hpp).
constexpr std::size_t emit_block = 4096;
static_assert(candidate_block <= emit_block, "a flush of candidates fits in a chunk of found pairs");

/// Below this many rectangles per part, a second core costs more than it saves.
constexpr std::size_t min_boxes_per_part = 16384;

/// Below this many rectangles (or strip entries) per unit taken as it comes
/// (work_shares.hpp), a unit's setup (its buffers, its strips' edges, its
/// counter) costs more than the balance it buys.
constexpr std::size_t min_boxes_per_unit = 4096;
constexpr std::size_t min_entries_per_unit = min_boxes_per_unit;

using clock_type = std::chrono::steady_clock;

inline double seconds_since(clock_type::time_point start) {
    return std::chrono::duration<double>(clock_type::now() - start).count();
}

}  // namespace obbsat::detail
