// What each part of obbsat_bench registers with Google Benchmark, and the
// counters they share. Parts that need an optional peer library are compiled
// only when CMake found it (OBBSAT_BENCH_WITH_BOX2D, OBBSAT_BENCH_WITH_BOOST).
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <ostream>

namespace obbsat_bench {

/// collide/<method>/<mode>/<backend>/pairs:<N>/threads:<T>[/density:<d>] for
/// every method and every backend this CPU runs; one line on `skipped` per
/// backend it cannot run.
void register_collide_benchmarks(std::ostream& skipped);

/// collide64/<method>/<poses|corners>/<backend>/pairs:262144/threads:<1|2>: collide_pairs
/// over the double stores, for every method that runs on them, on the scalar
/// backend and the best this CPU runs (bench_collide64.cpp).
void register_collide64_benchmarks();

/// convert/poses_to_corners/<backend>/poses:<N> for every backend this CPU
/// runs, convert/corners_from_angles/poses:<N> and convert/poses_from_angles/poses:<N>.
void register_convert_benchmarks();

/// contacts/poses/indexed/<backend>/pairs:<N>/threads:1 (contact_pairs) and
/// contacts/local_verdicts/poses/indexed/<backend>/... (local's verdicts on
/// the same pairs) and distances/poses/indexed/<backend>/... (distance_pairs)
/// at 4K and 256K pairs, for every backend this CPU runs.
void register_contact_benchmarks();

/// contacts/poses/indexed/box2d/pairs:<N>/threads:1: b2CollidePolygons on the contact rows' pairs.
void register_box2d_contact_peer();

/// peer/box2d_collide_polygons/pairs:<N> and peer/box2d_test_overlap/pairs:<N>.
void register_box2d_peers();

/// peer/boost_geometry_intersects/pairs:<N>.
void register_boost_geometry_peers();

/// Whole-scene queries, obbsat's (bench_scene.cpp): scene/<method>/<store>/<tail>
/// (find_pairs, a fresh query each time) and frame/<method>/<store>/<tail> (one
/// pair_finder, the boxes moving between calls) for exact and local on poses,
/// sat4 and exact on corners, where <tail> is
/// boxes:<N>/sizes:<uniform|mixed>/threads:<T> (scene_harness.hpp).
void register_scene_benchmarks();

/// engine_frame/<scene>/boxes:<N>/threads:<T> and engine_cold/...: pair_finder
/// and find_pairs over the frames of engine-shaped scenes (engine_scenes.hpp),
/// up to 10^6 boxes (bench_engine.cpp).
void register_engine_benchmarks();

/// floor/boxes:<N>/threads:1 from 10^5 boxes: bounds, keys, one radix sort and
/// the answer written out, on the scene of scene/exact/poses (bench_engine.cpp).
void register_floor_benchmarks();

/// busy_core/local/poses/boxes:1000000/sizes:uniform/threads:<1|2>/spinner:<off|on>:
/// find_pairs with and without a thread spinning on one core (bench_busy_core.cpp).
void register_busy_core_benchmarks();

/// peer_scene/grid/<tail> and peer_frame/grid/<tail>: a uniform grid, then obbsat's exact narrowphase.
void register_grid_scene_peer();

/// peer_scene/box2d/<tail> and peer_frame/box2d/<tail>: b2BroadPhase and b2CollidePolygons,
/// threads:1, up to 10^5 boxes; one line on `skipped` per box count left out.
void register_box2d_scene_peer(std::ostream& skipped);

/// peer_scene/rtree/<tail> and peer_frame/rtree/<tail>: Boost.Geometry's R-tree,
/// then obbsat's exact narrowphase.
void register_rtree_scene_peer();

/// Sets pairs_per_second and ns_per_pair from the real time of the run:
/// `pairs` are decided per iteration.
inline void set_pair_rate_counters(benchmark::State& state, std::size_t pairs) {
    const auto per_iteration = static_cast<double>(pairs);
    state.counters["pairs_per_second"] =
        benchmark::Counter(per_iteration, benchmark::Counter::kIsIterationInvariantRate);
    // Rate of (pairs * 1e-9) per second, inverted: seconds per 1e-9 pairs,
    // which is nanoseconds per pair.
    state.counters["ns_per_pair"] = benchmark::Counter(
        per_iteration * 1e-9, static_cast<benchmark::Counter::Flags>(
                                  benchmark::Counter::kIsIterationInvariantRate |
                                  benchmark::Counter::kInvert));
}

}  // namespace obbsat_bench
