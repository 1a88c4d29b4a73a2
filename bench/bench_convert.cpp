// Benchmarks of getting a scene's poses into obbsat: poses with a rotation
// vector to corner records in SIMD (convert_to_corners, every backend this CPU
// runs, checked byte for byte against the scalar reference before it is
// timed), and beside it the conversions from angles (sin and cos per box).
#include "bench_registry.hpp"
#include "bench_workload.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/ref/pose_corners.hpp>

#include <benchmark/benchmark.h>

#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace obbsat_bench {

namespace {

/// The scene's rectangles as poses with an angle (the input of the angle rows).
std::vector<obbsat::pose> angle_poses_of(workload& w) {
    std::vector<obbsat::pose> out(w.records().size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = obbsat::pose_of(w.records()[i]);
    }
    return out;
}

void set_box_counters(benchmark::State& state, std::size_t boxes) {
    state.counters["ns_per_box"] = benchmark::Counter(
        static_cast<double>(boxes) * 1e-9,
        static_cast<benchmark::Counter::Flags>(benchmark::Counter::kIsIterationInvariantRate |
                                               benchmark::Counter::kInvert));
}

void register_to_corners(obbsat::backend use, std::size_t pairs) {
    const std::string name = std::string("convert/poses_to_corners/") + obbsat::backend_name(use) +
                             "/poses:" + std::to_string(pairs / 2);
    benchmark::RegisterBenchmark(name.c_str(), [use, pairs](benchmark::State& state) {
        try {
            workload& w = workload_for(pairs, obbsat::scene_density::typical);
            const obbsat::pose_records& poses = w.poses();
            std::vector<obbsat::rect> corners(poses.size());
            if (obbsat::convert_to_corners(poses, corners.data(), use) != use) {
                state.SkipWithError("the backend asked for did not run");
                return;
            }
            for (std::size_t i = 0; i < poses.size(); ++i) {
                const obbsat::rect expected = obbsat::ref::corners_of(poses[i]);
                if (std::memcmp(&expected, &corners[i], sizeof expected) != 0) {
                    state.SkipWithError(("corners of pose " + std::to_string(i) + " differ from the reference").c_str());
                    return;
                }
            }
            for (auto _ : state) {
                obbsat::convert_to_corners(poses, corners.data(), use);
                benchmark::DoNotOptimize(corners.data());
                benchmark::ClobberMemory();
            }
            set_box_counters(state, poses.size());
        } catch (const std::exception& e) {
            state.SkipWithError(e.what());
        }
    })->UseRealTime()->Unit(benchmark::kMicrosecond);
}

template <class Convert>
void register_from_angles(const char* what, std::size_t pairs, Convert convert) {
    const std::string name = std::string("convert/") + what + "/poses:" + std::to_string(pairs / 2);
    benchmark::RegisterBenchmark(name.c_str(), [pairs, convert](benchmark::State& state) {
        try {
            workload& w = workload_for(pairs, obbsat::scene_density::typical);
            const std::vector<obbsat::pose> poses = angle_poses_of(w);
            for (auto _ : state) {
                auto converted = convert(poses);
                benchmark::DoNotOptimize(converted.data());
                benchmark::ClobberMemory();
            }
            set_box_counters(state, poses.size());
        } catch (const std::exception& e) {
            state.SkipWithError(e.what());
        }
    })->UseRealTime()->Unit(benchmark::kMicrosecond);
}

}  // namespace

void register_convert_benchmarks() {
    for (const std::size_t pairs : grid_sizes) {
        for (const obbsat::backend use : {obbsat::backend::scalar, obbsat::backend::sse2, obbsat::backend::avx2,
                                          obbsat::backend::avx512}) {
            if (obbsat::cpu_supports(use)) {
                register_to_corners(use, pairs);
            }
        }
        register_from_angles("corners_from_angles", pairs, [](const std::vector<obbsat::pose>& poses) {
            return obbsat::rect_records::from_poses(poses);
        });
        register_from_angles("poses_from_angles", pairs, [](const std::vector<obbsat::pose>& poses) {
            return obbsat::pose_records::from_angles(poses);
        });
    }
}

}  // namespace obbsat_bench
