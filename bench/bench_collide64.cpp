// collide64/<method>/<store>/<backend>/pairs:<N>/threads:<T>: collide_pairs over the
// double stores (poses and corners on the scalar backend and on the best this
// CPU runs) (obbsat/collide64.hpp) on the typical scene of the collide
// rows, its poses widened to double and moved to UTM-like coordinates
// (500000.125, 5712345.5), every value exact. Each row first checks its
// verdicts against the double scalar references, pair by pair, then times.
// The float rows collide/<method>/indexed_sorted/.../poses are the same pairs
// in float32.
//
// collide64/<method>/pose_stream/<backend>/pairs:4096/threads:1: collide_stream
// over two pose_soa64, a[i] against b[i], 4096 pairs (the first pairs of the
// list above); collide64/<method>/pose_stream_records/...: the same over two
// pose_records64. The float rows of the same size are
// collide/<method>/stream/.../store:poses (pose_soa) and .../store:poses/records.
#include "bench_registry.hpp"
#include "bench_workload.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/pose_soa64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace obbsat_bench {

namespace {

constexpr std::size_t double_pairs = 262144;

constexpr std::size_t double_stream_pairs = 4096;

struct double_workload {
    obbsat::pose_records64 poses;
    obbsat::rect_records64 corners;
    const std::vector<obbsat::pair_index>* pairs;
    obbsat::pose_records64 stream_a, stream_b;  ///< the poses of the first 4096 sorted pairs
    obbsat::pose_soa64 soa_a, soa_b;             ///< the same poses as arrays
};

obbsat::rect64 corners_of(const obbsat::rect_pose64& p) {
    const double c = p.rotation.x, s = p.rotation.y, hx = p.half_extents.x, hy = p.half_extents.y;
    auto at = [&](double a, double b) {
        return obbsat::point64{p.center.x + a * c - b * s, p.center.y + a * s + b * c};
    };
    return obbsat::rect64{at(-hx, hy), at(hx, hy), at(hx, -hy), at(-hx, -hy)};
}

double_workload& double_workload_of() {
    static std::unique_ptr<double_workload> built;
    if (!built) {
        workload& w = workload_for(double_pairs, obbsat::scene_density::typical);
        const obbsat::pose_records& poses = w.poses();
        std::vector<obbsat::rect_pose64> wide;
        std::vector<obbsat::rect64> corners;
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const obbsat::rect_pose p = poses[i];
            const obbsat::rect_pose64 q{{500000.125 + p.center.x, 5712345.5 + p.center.y},
                                        {p.half_extents.x, p.half_extents.y},
                                        {p.rotation.x, p.rotation.y}};
            wide.push_back(q);
            corners.push_back(corners_of(q));
        }
        built.reset(new double_workload{obbsat::pose_records64(wide), obbsat::rect_records64(corners),
                                        &w.sorted_pairs(), {}, {}, {}, {}});
        const std::vector<obbsat::pair_index>& first = w.sorted_pairs();
        for (std::size_t i = 0; i < double_stream_pairs; ++i) {
            built->stream_a.push_back(wide[first[i].a]);
            built->stream_b.push_back(wide[first[i].b]);
        }
        built->soa_a = obbsat::pose_soa64(built->stream_a);
        built->soa_b = obbsat::pose_soa64(built->stream_b);
    }
    return *built;
}

bool reference(obbsat::method m, const obbsat::rect_pose64& a, const obbsat::rect_pose64& b) {
    switch (m) {
        case obbsat::method::exact: return obbsat::ref::exact(a, b);
        case obbsat::method::conservative: return obbsat::ref::conservative(a, b);
        default: return obbsat::ref::local(a, b);
    }
}

bool reference(obbsat::method m, const obbsat::rect64& a, const obbsat::rect64& b) {
    return m == obbsat::method::exact ? obbsat::ref::exact(a, b) : obbsat::ref::conservative(a, b);
}

/// Times `run(verdicts, options)` deciding `count` pairs, pair_at(i) giving pair
/// i's two rectangles, after checking its verdicts against the references.
template <class Run, class PairAt>
void time_case(benchmark::State& state, std::size_t count, obbsat::method m, obbsat::backend use, unsigned threads,
               const Run& run, const PairAt& pair_at) {
    obbsat::collide_options options;
    options.test = m;
    options.use = use;
    options.threads = threads;
    std::size_t slow = 0;
    options.slow_path_pairs = &slow;
    std::vector<std::uint8_t> verdicts(count);
    run(verdicts.data(), options);
    for (std::size_t i = 0; i < count; ++i) {
        const auto [a, b] = pair_at(i);
        if (verdicts[i] != (reference(m, a, b) ? 1 : 0)) {
            state.SkipWithError(("pair " + std::to_string(i) + " differs from the double reference").c_str());
            return;
        }
    }
    for (auto _ : state) {
        run(verdicts.data(), options);
        benchmark::DoNotOptimize(verdicts.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(count));
    set_pair_rate_counters(state, count);
    state.counters["slow_path_pairs"] = static_cast<double>(slow);
}

template <class Store>
void run_case(benchmark::State& state, const Store& store, const std::vector<obbsat::pair_index>& pairs,
              obbsat::method m, obbsat::backend use, unsigned threads) {
    time_case(
        state, pairs.size(), m, use, threads,
        [&](std::uint8_t* verdicts, const obbsat::collide_options& options) {
            obbsat::collide_pairs(store, pairs.data(), pairs.size(), verdicts, options);
        },
        [&](std::size_t i) { return std::make_pair(store[pairs[i].a], store[pairs[i].b]); });
}

template <class Store>
void run_stream(benchmark::State& state, const Store& a, const Store& b, obbsat::method m, obbsat::backend use) {
    time_case(
        state, a.size(), m, use, 1,
        [&](std::uint8_t* verdicts, const obbsat::collide_options& options) {
            obbsat::collide_stream(a, b, verdicts, options);
        },
        [&](std::size_t i) { return std::make_pair(a[i], b[i]); });
}

}  // namespace

void register_collide64_benchmarks() {
    auto row = [](obbsat::method m, const char* store, obbsat::backend use, unsigned threads) {
        return std::string("collide64/") + obbsat::method_name(m) + "/" + store + "/" + obbsat::backend_name(use) +
               "/pairs:" + std::to_string(double_pairs) + "/threads:" + std::to_string(threads);
    };
    std::vector<obbsat::backend> pose_backends{obbsat::backend::scalar};
    if (obbsat::best_supported_backend() != obbsat::backend::scalar) {
        pose_backends.push_back(obbsat::best_supported_backend());
    }
    for (const unsigned threads : {1u, 2u}) {
        for (const obbsat::method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
            for (const obbsat::backend use : pose_backends) {
                benchmark::RegisterBenchmark(row(m, "poses", use, threads).c_str(),
                                             [m, use, threads](benchmark::State& state) {
                                                 double_workload& w = double_workload_of();
                                                 run_case(state, w.poses, *w.pairs, m, use, threads);
                                             })
                    ->UseRealTime()
                    ->Unit(benchmark::kMicrosecond);
            }
        }
        for (const obbsat::method m : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
            for (const obbsat::backend use : pose_backends) {
                if (threads != 1) {
                    continue;  // 4096 pairs take one core
                }
                const auto name = [&](const char* stream) {
                    return std::string("collide64/") + obbsat::method_name(m) + "/" + stream + "/" +
                           obbsat::backend_name(use) + "/pairs:" + std::to_string(double_stream_pairs) + "/threads:1";
                };
                benchmark::RegisterBenchmark(name("pose_stream").c_str(),
                                             [m, use](benchmark::State& state) {
                                                 double_workload& w = double_workload_of();
                                                 run_stream(state, w.soa_a, w.soa_b, m, use);
                                             })
                    ->UseRealTime()
                    ->Unit(benchmark::kMicrosecond);
                benchmark::RegisterBenchmark(name("pose_stream_records").c_str(),
                                             [m, use](benchmark::State& state) {
                                                 double_workload& w = double_workload_of();
                                                 run_stream(state, w.stream_a, w.stream_b, m, use);
                                             })
                    ->UseRealTime()
                    ->Unit(benchmark::kMicrosecond);
            }
        }
        // Corners on the same backends as poses: the scalar references and the best lanes.
        const std::vector<obbsat::backend>& corner_backends = pose_backends;
        for (const obbsat::method m : obbsat::methods_on_doubles(obbsat::store_kind::corners)) {
            for (const obbsat::backend use : corner_backends) {
                benchmark::RegisterBenchmark(row(m, "corners", use, threads).c_str(),
                                             [m, use, threads](benchmark::State& state) {
                                                 double_workload& w = double_workload_of();
                                                 run_case(state, w.corners, *w.pairs, m, use, threads);
                                             })
                    ->UseRealTime()
                    ->Unit(benchmark::kMicrosecond);
            }
        }
    }
}

}  // namespace obbsat_bench
