// Engine-shaped scenes (engine_scenes.hpp) and the floor of a scene query.
//
//   engine_frame/<scene>/boxes:<N>/threads:<T>  one obbsat::pair_finder over
//       the scene's frames: warm_frames untimed, then one frame per
//       iteration, timed_frames of them (the step to the next frame is not
//       timed). Counters reused_candidates: the share of timed frames
//       answered from kept candidates (find_pairs_stats::reused_candidates);
//       candidates_per_box and kept_per_box: the candidates tested, and the
//       candidates of widened bounds kept for the next frames, per box;
//       resting: the share answered by plain queries because keeping cost
//       more than plain queries did (find_pairs_stats::kept_resting).
//       A scene whose boxes have ids (spawn_despawn) passes them
//       (box_view::with_ids), so that the finder follows rows that come and
//       go; engine_frame/drift is the same scene with no rows changed, so
//       spawn_despawn over drift reads the cost of the change from one run,
//       and engine_frame/drift_ids is drift passing ids (the same each
//       frame): spawn_despawn over drift_ids is the cost of the change alone,
//       the id match of every frame left out of it.
//       A scene with pair filters (spawn_despawn_filtered) passes them to
//       both rows (box_view::with_filters); its reused_candidates counter
//       shows whether frames whose rows and filters changed are answered
//       from kept candidates (the filters follow the ids).
//   engine_cold/<scene>/boxes:<N>/threads:<T>   a fresh obbsat::find_pairs
//       on the same frames.
// Both on poses, method exact. Counters ns_per_box and pairs_per_box (per
// frame, mean over the timed frames). Before either row of a scene, box count
// and thread count is timed, a pair_finder and find_pairs are run side by
// side on the first frames (check_frames of them up to check_limit boxes,
// 4 beyond: the finder's third call is its first answer from kept
// candidates) and must give the same pairs.
//
//   floor/boxes:<N>/threads:1  what memory and one sort cost on this machine
//       for the uniform scene of scene/exact/poses/boxes:<N>/sizes:uniform:
//       one read of the poses computing each box's bounds
//       (obbsat::ref::bounds_of, scalar) into four arrays and their extent,
//       the strips and sort keys of the query (its strip_grid: lowest strip,
//       quantized lo_x), one radix sort of (key, index) (the library's own
//       radix_sort, one thread), and the answer's pairs written out (copied
//       from find_pairs' answer, computed once before timing). Every buffer
//       is kept across iterations, so no page is faulted in while timed.
#include "bench_registry.hpp"
#include "engine_scenes.hpp"
#include "scene_workload.hpp"

#include "scene/strip_grid.hpp"
#include "sort/radix_sort.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/ref/bounds.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace obbsat_bench {

namespace {

/// Frames before the timed ones: a pair_finder keeps candidates from its
/// second call and answers from them from its third.
constexpr int warm_frames = 8;
/// Frames timed per row, one per iteration.
constexpr int timed_frames = 32;
/// Frames compared between pair_finder and find_pairs before timing.
constexpr int check_frames = warm_frames + 4;
/// Engine rows are registered up to this many boxes.
constexpr std::size_t engine_max_boxes = 1000000;

obbsat::collide_options exact_options(unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.threads = threads;
    return options;
}

/// The current frame's rows, with their filters when the scene gives filters.
obbsat::box_view cold_view(const engine_sequence& frames) {
    const obbsat::box_view rows(frames.poses());
    const obbsat::pair_filters filters = frames.filters();
    return filters.any() ? rows.with_filters(filters) : rows;
}

/// The same, with their ids when the scene gives ids.
obbsat::box_view frame_view(const engine_sequence& frames) {
    const obbsat::box_view rows = cold_view(frames);
    const std::vector<std::uint64_t>* ids = frames.ids();
    return ids != nullptr ? rows.with_ids(*ids) : rows;
}

/// "" when a pair_finder and find_pairs agree on the first frames, else what differs.
const std::string& check_engine_scene(engine_scene scene, std::size_t boxes, unsigned threads) {
    static std::map<std::tuple<engine_scene, std::size_t, unsigned>, std::string> checked;
    const auto key = std::make_tuple(scene, boxes, threads);
    auto found = checked.find(key);
    if (found != checked.end()) {
        return found->second;
    }
    std::string error;
    const std::unique_ptr<engine_sequence> frames = make_engine_sequence(scene, boxes);
    obbsat::pair_finder finder(exact_options(threads));
    const int count = boxes <= check_limit ? check_frames : 4;
    for (int t = 0; t < count && error.empty(); ++t, frames->step()) {
        const std::vector<obbsat::pair_index>& kept = finder.find(frame_view(*frames));
        const std::vector<obbsat::pair_index> cold = obbsat::find_pairs(cold_view(*frames), exact_options(threads));
        const auto same = [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
            return x.a == y.a && x.b == y.b;
        };
        if (kept.size() != cold.size() || !std::equal(kept.begin(), kept.end(), cold.begin(), same)) {
            error = "frame " + std::to_string(t) + ": pair_finder found " + std::to_string(kept.size()) +
                    " pairs, find_pairs " + std::to_string(cold.size()) + ", not the same";
        }
    }
    return checked.emplace(key, error).first->second;
}

void set_per_box_counters(benchmark::State& state, std::size_t boxes, double pairs) {
    const auto n = static_cast<double>(boxes);
    // Rate of (boxes * 1e-9) per second, inverted: nanoseconds per box.
    state.counters["ns_per_box"] =
        benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                         benchmark::Counter::kIsIterationInvariantRate |
                                         benchmark::Counter::kInvert));
    state.counters["pairs_per_box"] = benchmark::Counter(pairs / n, benchmark::Counter::kAvgIterations);
}

void run_engine_row(benchmark::State& state, engine_scene scene, std::size_t boxes, unsigned threads,
                    bool kept) {
    try {
        const std::string& error = check_engine_scene(scene, boxes, threads);
        if (!error.empty()) {
            state.SkipWithError(error.c_str());
            return;
        }
        const std::unique_ptr<engine_sequence> frames = make_engine_sequence(scene, boxes);
        obbsat::pair_finder finder(exact_options(threads));
        for (int t = 0; t < warm_frames; ++t, frames->step()) {
            if (kept) {
                finder.find(frame_view(*frames));
            }
        }
        std::vector<obbsat::pair_index> cold;
        double pairs = 0, from_kept = 0, resting = 0, candidates = 0, kept_candidates = 0;
        for (auto _ : state) {
            if (kept) {
                const std::vector<obbsat::pair_index>& found = finder.find(frame_view(*frames));
                benchmark::DoNotOptimize(found.data());
                pairs += static_cast<double>(found.size());
                from_kept += finder.stats().reused_candidates ? 1.0 : 0.0;
                resting += finder.stats().kept_resting ? 1.0 : 0.0;
                candidates += static_cast<double>(finder.stats().candidates);
                kept_candidates += static_cast<double>(finder.stats().kept_candidates);
            } else {
                cold = obbsat::find_pairs(cold_view(*frames), exact_options(threads));
                benchmark::DoNotOptimize(cold.data());
                pairs += static_cast<double>(cold.size());
            }
            state.PauseTiming();
            frames->step();
            state.ResumeTiming();
        }
        set_per_box_counters(state, frames->poses().size(), pairs);
        if (kept) {
            const auto n = static_cast<double>(frames->poses().size());
            state.counters["reused_candidates"] = benchmark::Counter(from_kept, benchmark::Counter::kAvgIterations);
            state.counters["resting"] = benchmark::Counter(resting, benchmark::Counter::kAvgIterations);
            state.counters["candidates_per_box"] =
                benchmark::Counter(candidates / n, benchmark::Counter::kAvgIterations);
            state.counters["kept_per_box"] = benchmark::Counter(kept_candidates / n, benchmark::Counter::kAvgIterations);
        }
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

/// The answer of the uniform scene of `boxes`, computed once.
const std::vector<obbsat::pair_index>& floor_answer(std::size_t boxes) {
    static std::map<std::size_t, std::vector<obbsat::pair_index>> answers;
    auto found = answers.find(boxes);
    if (found == answers.end()) {
        scene_workload& w = scene_workload_for(boxes, obbsat::scene_sizes::uniform);
        found = answers.emplace(boxes, obbsat::find_pairs(w.poses(scene_frame::as_generated), exact_options(1)))
                    .first;
    }
    return found->second;
}

void run_floor_row(benchmark::State& state, std::size_t boxes) {
    try {
        scene_workload& w = scene_workload_for(boxes, obbsat::scene_sizes::uniform);
        const obbsat::pose_records& poses = w.poses(scene_frame::as_generated);
        const std::vector<obbsat::pair_index>& answer = floor_answer(boxes);
        const std::size_t n = poses.size();
        std::vector<float> lo_x(n), lo_y(n), hi_x(n), hi_y(n);
        std::vector<std::uint32_t> keys(n), values(n);
        obbsat::detail::radix_buffer packed, spare;
        std::vector<obbsat::pair_index> out(answer.size());
        for (auto _ : state) {
            // One read of the poses: bounds and their extent.
            float x_low = std::numeric_limits<float>::infinity(), x_high = -x_low;
            float y_low = x_low, y_high = -x_low;
            double heights = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(poses[i]);
                lo_x[i] = b.lo_x;
                lo_y[i] = b.lo_y;
                hi_x[i] = b.hi_x;
                hi_y[i] = b.hi_y;
                x_low = std::min(x_low, b.lo_x);
                x_high = std::max(x_high, b.hi_x);
                y_low = std::min(y_low, b.lo_y);
                y_high = std::max(y_high, b.hi_y);
                heights += static_cast<double>(b.hi_y - b.lo_y);
            }
            // The strips and keys of the query's order, and one sort.
            const obbsat::detail::bounds_extent extent{x_low, x_high, y_low, y_high,
                                                       n == 0 ? 0.0 : heights / static_cast<double>(n)};
            const obbsat::detail::strip_grid grid = obbsat::detail::grid_for(extent, n, 2.0);
            for (std::size_t i = 0; i < n; ++i) {
                keys[i] = grid.key_of(lo_x[i], lo_y[i]);
                values[i] = static_cast<std::uint32_t>(i);
            }
            obbsat::detail::radix_sort(keys.data(), values.data(), n, grid.key_bits(), packed, spare, 1);
            // The answer's pairs written out.
            std::copy(answer.begin(), answer.end(), out.begin());
            benchmark::DoNotOptimize(values.data());
            benchmark::DoNotOptimize(hi_x.data());
            benchmark::DoNotOptimize(hi_y.data());
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
        }
        set_per_box_counters(state, n, static_cast<double>(answer.size()) * static_cast<double>(state.iterations()));
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
    }
}

}  // namespace

void register_engine_benchmarks() {
    const std::vector<std::size_t> counts = scene_box_counts_to_register();
    // Each frame row next to its cold row, so that both see the machine as it was.
    for (const engine_scene scene : engine_scenes) {
        for (const std::size_t boxes : counts) {
            if (boxes > engine_max_boxes) {
                continue;
            }
            for (const unsigned threads : {1u, 2u}) {
                for (const bool kept : {true, false}) {
                    const std::string name = std::string(kept ? "engine_frame/" : "engine_cold/") +
                                             engine_scene_name(scene) + "/boxes:" + std::to_string(boxes) +
                                             "/threads:" + std::to_string(threads);
                    benchmark::RegisterBenchmark(name.c_str(),
                                                 [scene, boxes, threads, kept](benchmark::State& state) {
                                                     run_engine_row(state, scene, boxes, threads, kept);
                                                 })
                        ->UseRealTime()
                        ->Iterations(timed_frames)
                        ->Unit(benchmark::kMillisecond);
                }
            }
        }
    }
}

void register_floor_benchmarks() {
    for (const std::size_t boxes : scene_box_counts_to_register()) {
        if (boxes < 100000) {
            continue;
        }
        const std::string name = "floor/boxes:" + std::to_string(boxes) + "/threads:1";
        benchmark::RegisterBenchmark(name.c_str(), [boxes](benchmark::State& state) { run_floor_row(state, boxes); })
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace obbsat_bench
