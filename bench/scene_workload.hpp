// The scenes of the whole-scene benchmarks (scene/, frame/, peer_scene/,
// peer_frame/): one seeded make_pose_scene per box count and size spread, two
// colliding pairs per box, kept for the rest of the run so that a 4M-box
// scene is generated once per process however many rows use it.
//
// Each scene has two frames: as generated, and moved, where every box is
// displaced by ±frame_step in x and in y (signs seeded per box). A frame
// benchmark alternates between the two, so the boxes move a little on every
// call and the scene never drifts, with no motion inside the timed loop.
//
// The reference a row is checked against (before it is timed, up to
// check_limit boxes) is computed here without find_pairs: a plain sweep over
// x of obbsat::ref::bounds_of lists the pairs whose bounds overlap, and the
// method's scalar reference decides each. That is find_pairs' contract
// exactly (obbsat/find_pairs.hpp), so obbsat and the exact peers must match it
// pair for pair.
#pragma once

#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace obbsat_bench {

/// Box counts of the scene benchmarks. OBBSAT_BENCH_SCENE_BOXES (a comma
/// separated list, e.g. "10000,100000") registers other counts instead.
inline constexpr std::size_t scene_box_counts[] = {10000, 100000, 1000000, 4000000};

/// Size spreads of the scene benchmarks, each a row of its own.
inline constexpr obbsat::scene_sizes scene_size_spreads[] = {obbsat::scene_sizes::uniform,
                                                              obbsat::scene_sizes::mixed};

/// Colliding pairs per box asked of make_pose_scene.
inline constexpr double scene_pairs_per_box = 2.0;

/// How far a box moves between the two frames, in x and in y.
inline constexpr float frame_step = 0.05f;

/// Rows up to this many boxes are checked against the reference before timing.
inline constexpr std::size_t check_limit = 100000;

/// The box counts to register: scene_box_counts, or OBBSAT_BENCH_SCENE_BOXES.
/// Throws std::runtime_error when that variable is not a list of positive counts.
std::vector<std::size_t> scene_box_counts_to_register();

/// "boxes:<N>/sizes:<uniform|mixed>/threads:<T>", the tail of every scene row's name.
std::string scene_name_tail(std::size_t boxes, obbsat::scene_sizes sizes, unsigned threads);

/// The two frames of a scene.
enum class scene_frame { as_generated, moved };

/// The frame a frame benchmark's call after `f` uses.
inline scene_frame other_frame(scene_frame f) {
    return f == scene_frame::as_generated ? scene_frame::moved : scene_frame::as_generated;
}

class scene_workload {
public:
    scene_workload(std::size_t boxes, obbsat::scene_sizes sizes);

    std::size_t size() const { return poses_[0]->size(); }

    /// The poses of frame `f`; the moved frame is built on first use.
    const obbsat::pose_records& poses(scene_frame f);
    /// corner_records_of(poses(f)); built on first use.
    const obbsat::rect_records& corners(scene_frame f);

    /// Every pair (i, j), i < j, of frame `f` in store `store` whose
    /// obbsat::ref::bounds_of overlap and that the scalar reference of `test`
    /// calls colliding, sorted by i then j; computed on first use.
    const std::vector<obbsat::pair_index>& reference_pairs(scene_frame f, obbsat::store_kind store,
                                                           obbsat::method test);

private:
    const std::vector<obbsat::pair_index>& candidate_pairs(scene_frame f, obbsat::store_kind store);

    using frame_store = std::pair<scene_frame, obbsat::store_kind>;
    std::unique_ptr<obbsat::pose_records> poses_[2];
    std::unique_ptr<obbsat::rect_records> corners_[2];
    std::map<frame_store, std::vector<obbsat::pair_index>> candidates_;
    std::map<std::pair<frame_store, obbsat::method>, std::vector<obbsat::pair_index>> references_;
};

/// The shared scene of that box count and size spread, built on first request.
/// The benchmarks run one at a time, so the cache needs no lock.
scene_workload& scene_workload_for(std::size_t boxes, obbsat::scene_sizes sizes);

}  // namespace obbsat_bench
