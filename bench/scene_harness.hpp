// How a whole-scene query is benchmarked, obbsat's and every peer's alike:
// from a scene's poses to the list of its colliding pairs, timed in real time
// (a query may run on several cores).
//
// Two rows per query, box count, size spread and thread count:
//   <cold prefix>/boxes:<N>/sizes:<S>/threads:<T>   a fresh query per iteration:
//       everything built from the poses, answered, and torn down.
//   <frame prefix>/boxes:<N>/sizes:<S>/threads:<T>  one query kept across
//       iterations, each iteration on the other frame of the scene (every box
//       moved by ±frame_step): a simulation step. Two untimed calls, one on
//       each frame, come first.
// Counters: ns_per_box, pairs_per_box (pairs reported), candidates_per_box
// (pairs whose bounds overlap, handed to the narrowphase) and, for obbsat's
// pair_finder, reused_order (the share of iterations that repaired the
// previous order instead of sorting again) and kernel_ns_per_candidate (the
// method's kernels alone, per candidate, summed over the threads: the
// narrowphase's share of the sweep).
//
// Answers are taken in each query's own order: obbsat's come sorted by i,
// then j (find_pairs' contract, paid for in its rows), the peers' do not and
// are not sorted for them.
//
// Before timing, on scenes of up to check_limit boxes, the query's answers
// are compared with the scene's reference (scene_workload.hpp), once per row:
// on the as-generated frame for a cold row, on as generated, moved and as
// generated again for a frame row. An exact query that differs is an error
// naming how many pairs differ; a query with its own notion of contact
// (Box2D's polygon skin) reports agreement, peer_only and reference_only, the
// shares of the union of both pair sets, as the peer/* rows do.
#pragma once

#include "scene_workload.hpp"

#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace obbsat_bench {

/// One query's state on one scene: the first find builds everything it
/// needs from the frame's poses; later finds may reuse what they kept.
class scene_query {
public:
    virtual ~scene_query() = default;
    /// The colliding pairs (i, j), i < j, of frame `f`, in the query's own
    /// order; valid until the next call.
    virtual const std::vector<obbsat::pair_index>& find(scene_frame f) = 0;
    /// How many candidate pairs the last find handed to its narrowphase.
    virtual std::size_t candidates() const = 0;
    /// Whether the last find repaired the previous call's order; nothing for
    /// queries that keep no order.
    virtual std::optional<bool> reused_order() const { return std::nullopt; }
    /// Seconds the last find spent in its narrowphase kernels, summed over
    /// threads; nothing for queries that do not time them.
    virtual std::optional<double> kernel_seconds() const { return std::nullopt; }
};

/// The two rows of a query: a fresh query per iteration, or one kept.
enum class scene_row_kind { cold, frame };

/// Makes a fresh query for `threads` cores; called inside the timed loop of
/// a cold row, so it must only capture what prepare built.
using scene_query_factory = std::function<std::unique_ptr<scene_query>(unsigned threads)>;

/// Builds a query's own data for one scene and kind of row, untimed (e.g.
/// Box2D's shapes and body transforms), and returns its factory.
using scene_query_prepare = std::function<scene_query_factory(scene_workload& scene, scene_row_kind kind)>;

/// What a query's answer is checked against: the reference of `test` on
/// `store`. With must_match false the answer is only compared (agreement
/// counters), never an error.
struct scene_expectation {
    obbsat::store_kind store;
    obbsat::method test;
    bool must_match;
};

/// One query to benchmark, in cold and frame rows.
struct scene_rows {
    std::string cold_prefix;   ///< e.g. "scene/exact/poses", "peer_scene/box2d"
    std::string frame_prefix;  ///< e.g. "frame/exact/poses", "peer_frame/box2d"
    std::vector<unsigned> thread_counts;
    scene_expectation expected;
    scene_query_prepare prepare;
    /// Rows for larger scenes are not registered (a peer too slow for them).
    std::size_t max_boxes = static_cast<std::size_t>(-1);
};

/// Registers the cold and frame rows of `rows` for every box count of
/// scene_box_counts_to_register() up to rows.max_boxes, size spread and
/// thread count; returns the box counts it left out.
std::vector<std::size_t> register_scene_rows(const scene_rows& rows);

/// How two pair lists differ, compared as sets of (i, j) (order ignored).
struct pair_set_difference {
    std::size_t both = 0;
    std::size_t only_found = 0;
    std::size_t only_expected = 0;
};

/// The difference between `found` and `expected` as sets.
pair_set_difference compare_pair_sets(std::vector<obbsat::pair_index> found,
                                      std::vector<obbsat::pair_index> expected);

}  // namespace obbsat_bench
