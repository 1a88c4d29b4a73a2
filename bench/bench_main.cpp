// obbsat_bench: the obbsat batch API and its peers on the same seeded scenes.
// Lines about what is skipped go to stderr, so --benchmark_format=json on
// stdout stays valid JSON.
#include "bench_registry.hpp"

#include <obbsat/backend.hpp>

#include <benchmark/benchmark.h>

#include <exception>
#include <iostream>
#include <string>

#ifndef OBBSAT_BENCH_BUILD_TYPE
#define OBBSAT_BENCH_BUILD_TYPE "unknown"
#endif
#ifndef OBBSAT_BENCH_WITH_BOX2D
#define OBBSAT_BENCH_WITH_BOX2D 0
#endif
#ifndef OBBSAT_BENCH_WITH_BOOST
#define OBBSAT_BENCH_WITH_BOOST 0
#endif

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }

    std::string compiled;
    for (const obbsat::backend b : obbsat::compiled_backends()) {
        compiled += std::string(compiled.empty() ? "" : ",") + obbsat::backend_name(b);
    }
    benchmark::AddCustomContext("obbsat_build_type", OBBSAT_BENCH_BUILD_TYPE);
    benchmark::AddCustomContext("obbsat_compiled_backends", compiled);
    benchmark::AddCustomContext("obbsat_best_backend",
                                obbsat::backend_name(obbsat::best_supported_backend()));

    obbsat_bench::register_collide_benchmarks(std::cerr);
    obbsat_bench::register_collide64_benchmarks();
    obbsat_bench::register_convert_benchmarks();
    obbsat_bench::register_contact_benchmarks();
#if OBBSAT_BENCH_WITH_BOX2D
    obbsat_bench::register_box2d_peers();
    obbsat_bench::register_box2d_contact_peer();
#else
    std::cerr << "obbsat_bench: skipping peer/box2d_*: Box2D was not found when obbsat was configured\n";
#endif
#if OBBSAT_BENCH_WITH_BOOST
    obbsat_bench::register_boost_geometry_peers();
#else
    std::cerr << "obbsat_bench: skipping peer/boost_geometry_*: Boost.Geometry was not found when "
                 "obbsat was configured\n";
#endif

    // Whole scenes: obbsat's queries, then its peers on the same scenes.
    try {
        obbsat_bench::register_scene_benchmarks();
        obbsat_bench::register_floor_benchmarks();
        obbsat_bench::register_busy_core_benchmarks();
        obbsat_bench::register_engine_benchmarks();
        obbsat_bench::register_grid_scene_peer();
#if OBBSAT_BENCH_WITH_BOX2D
        obbsat_bench::register_box2d_scene_peer(std::cerr);
#else
        std::cerr << "obbsat_bench: skipping peer_scene/box2d/*, peer_frame/box2d/*: Box2D was not found "
                     "when obbsat was configured\n";
#endif
#if OBBSAT_BENCH_WITH_BOOST
        obbsat_bench::register_rtree_scene_peer();
#else
        std::cerr << "obbsat_bench: skipping peer_scene/rtree/*, peer_frame/rtree/*: Boost.Geometry was not "
                     "found when obbsat was configured\n";
#endif
    } catch (const std::exception& e) {
        std::cerr << "obbsat_bench: " << e.what() << "\n";
        return 1;
    }

    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
