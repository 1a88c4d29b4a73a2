// Benchmarks of the obbsat batch API: every method, batch mode, backend this
// CPU runs, batch size and thread count, each checked against the scalar
// reference before it is timed.
//
// Indexed modes run on rect_records, the store the library recommends for pair
// lists; the same pairs on rect_soa (one gather per coordinate) are the rows
// ending in /store:soa, so the gain of the packed store stays visible.
#include "bench_registry.hpp"
#include "bench_workload.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>

#include <benchmark/benchmark.h>

#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace obbsat_bench {

namespace {

enum class batch_mode {
    stream,          ///< collide_stream on A[i], B[i]
    indexed_sorted,  ///< collide_pairs on the pair list as the generator emits it
    indexed_random,  ///< collide_pairs on the same list, shuffled
};

/// Where a batch reads its rectangles from: corner records or structure of
/// arrays (indexed batches; corner streams always use rect_soa), or poses:
/// pose_soa for streams, pose_records for indexed batches (poses), and
/// pose_records for streams too (pose_records_stream), or rect_pose rows in
/// the caller's memory for indexed batches (pose_rows).
enum class rect_store { records, soa, poses, pose_records_stream, pose_rows };

const char* mode_name(batch_mode mode) {
    switch (mode) {
        case batch_mode::stream: return "stream";
        case batch_mode::indexed_sorted: return "indexed_sorted";
        case batch_mode::indexed_random: return "indexed_random";
    }
    return "unknown";
}

// The bytes a mode must move per pair at the very least, whatever the cache
// does for it: this is the denominator of the roofline's memory bound.
//   stream:  two rectangles of 4 float corners (2 x 32 bytes) read, one verdict
//            byte written: 65.
//   indexed: the 8-byte pair_index read, the two rectangles it names (2 x 32
//            bytes) read, one verdict byte written: 73.
// Neither counts cache-line waste: a rectangle fetched at random brings a
// whole 64-byte line (records) or eight of them (SoA), which is exactly what
// the measured rate compared with this minimum shows.
// Poses are stored in 32-byte records too (six floats and two of padding),
// so the same minimum holds for them.
double bytes_per_pair(batch_mode mode) {
    return mode == batch_mode::stream ? 65.0 : 73.0;
}

struct collide_case {
    obbsat::method test;
    batch_mode mode;
    obbsat::backend use;
    std::size_t pairs;
    unsigned threads;
    obbsat::scene_density density;
    rect_store store;
};

std::string case_name(const collide_case& c) {
    std::string name = std::string("collide/") + obbsat::method_name(c.test) + "/" +
                       mode_name(c.mode) + "/" + obbsat::backend_name(c.use) +
                       "/pairs:" + std::to_string(c.pairs) + "/threads:" + std::to_string(c.threads);
    if (c.density != obbsat::scene_density::typical) {
        name += std::string("/density:") + density_name(c.density);
    }
    if (c.mode != batch_mode::stream && c.store == rect_store::soa) {
        name += "/store:soa";
    }
    // A method that runs on corners too is marked when it runs on poses;
    // local runs on nothing else.
    const bool on_poses = c.store == rect_store::poses || c.store == rect_store::pose_records_stream ||
                          c.store == rect_store::pose_rows;
    if (on_poses && obbsat::runs_on(c.test, obbsat::store_kind::corners)) {
        name += "/store:poses";
    }
    if (c.store == rect_store::pose_records_stream) {
        name += "/records";
    }
    if (c.store == rect_store::pose_rows) {
        name += "/rows";
    }
    return name;
}

obbsat::backend run_batch(workload& w, const collide_case& c, std::uint8_t* verdicts) {
    obbsat::collide_options options;
    options.test = c.test;
    options.use = c.use;
    options.threads = c.threads;
    if (c.store == rect_store::pose_records_stream) {
        return obbsat::collide_stream(w.pose_stream_a(), w.pose_stream_b(), verdicts, options);
    }
    if (c.store == rect_store::pose_rows) {
        const obbsat::pair_index* pairs =
            c.mode == batch_mode::indexed_sorted ? w.sorted_pairs().data() : w.shuffled_pairs().data();
        const std::vector<obbsat::rect_pose>& rows = w.pose_rows();
        return obbsat::collide_pairs(rows.data(), rows.size(), pairs, c.pairs, verdicts, options);
    }
    if (c.store == rect_store::poses) {
        if (c.mode == batch_mode::stream) {
            return obbsat::collide_stream(w.pose_soa_stream_a(), w.pose_soa_stream_b(), verdicts, options);
        }
        const obbsat::pair_index* pairs =
            c.mode == batch_mode::indexed_sorted ? w.sorted_pairs().data() : w.shuffled_pairs().data();
        return obbsat::collide_pairs(w.poses(), pairs, c.pairs, verdicts, options);
    }
    switch (c.mode) {
        case batch_mode::stream:
            return obbsat::collide_stream(w.stream_a(), w.stream_b(), verdicts, options);
        case batch_mode::indexed_sorted:
        case batch_mode::indexed_random: {
            const obbsat::pair_index* pairs = c.mode == batch_mode::indexed_sorted
                                                  ? w.sorted_pairs().data()
                                                  : w.shuffled_pairs().data();
            return c.store == rect_store::records
                       ? obbsat::collide_pairs(w.records(), pairs, c.pairs, verdicts, options)
                       : obbsat::collide_pairs(w.rects(), pairs, c.pairs, verdicts, options);
        }
    }
    return obbsat::backend::automatic;
}

const std::vector<std::uint8_t>& expected_verdicts(workload& w, const collide_case& c) {
    // The streams follow the sorted list, so they share its reference.
    if (c.store == rect_store::poses || c.store == rect_store::pose_records_stream ||
        c.store == rect_store::pose_rows) {
        return c.mode == batch_mode::indexed_random ? w.pose_shuffled_reference(c.test)
                                                    : w.pose_sorted_reference(c.test);
    }
    return c.mode == batch_mode::indexed_random ? w.shuffled_reference(c.test)
                                                : w.sorted_reference(c.test);
}

/// Empty if the batch ran on the backend asked for and matches the reference
/// byte for byte; otherwise what went wrong.
std::string check_against_reference(workload& w, const collide_case& c,
                                    std::vector<std::uint8_t>& verdicts) {
    const obbsat::backend ran = run_batch(w, c, verdicts.data());
    if (ran != c.use) {
        return std::string("asked for backend ") + obbsat::backend_name(c.use) + ", " +
               obbsat::backend_name(ran) + " ran";
    }
    const std::vector<std::uint8_t>& expected = expected_verdicts(w, c);
    const std::vector<obbsat::pair_index>& pairs =
        c.mode == batch_mode::indexed_random ? w.shuffled_pairs() : w.sorted_pairs();
    for (std::size_t i = 0; i < c.pairs; ++i) {
        if (verdicts[i] != expected[i]) {
            return "verdict of pair " + std::to_string(i) + " (" + std::to_string(pairs[i].a) +
                   ", " + std::to_string(pairs[i].b) + ") is " + std::to_string(verdicts[i]) +
                   ", the scalar reference says " + std::to_string(expected[i]);
        }
    }
    return {};
}

void run_collide_case(benchmark::State& state, const collide_case& c, bool& checked) {
    try {
        workload& w = workload_for(c.pairs, c.density);
        std::vector<std::uint8_t> verdicts(c.pairs);
        // Google Benchmark enters this function several times per benchmark
        // (to size the iteration count, then per repetition); one check of
        // the verdicts is enough, the timed batches are the same call.
        if (!checked) {
            const std::string problem = check_against_reference(w, c, verdicts);
            if (!problem.empty()) {
                state.SkipWithError(problem.c_str());
                return;
            }
            checked = true;
        }
        for (auto _ : state) {
            run_batch(w, c, verdicts.data());
            benchmark::DoNotOptimize(verdicts.data());
            benchmark::ClobberMemory();
        }
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    set_pair_rate_counters(state, c.pairs);
    state.counters["bytes_per_pair"] = bytes_per_pair(c.mode);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(c.pairs) *
                            static_cast<std::int64_t>(bytes_per_pair(c.mode)));
}

void register_case(const collide_case& c) {
    auto checked = std::make_shared<bool>(false);
    // Real time: with threads > 1 the library decides pairs on other cores,
    // whose CPU time the benchmark's own thread never sees.
    benchmark::RegisterBenchmark(case_name(c).c_str(),
                                 [c, checked](benchmark::State& state) {
                                     run_collide_case(state, c, *checked);
                                 })
        ->UseRealTime()
        ->Unit(benchmark::kMicrosecond);
}

}  // namespace

void register_collide_benchmarks(std::ostream& skipped) {
    const obbsat::backend concrete[] = {obbsat::backend::scalar, obbsat::backend::sse2,
                                        obbsat::backend::avx2, obbsat::backend::avx512};
    std::vector<obbsat::backend> runnable;
    for (const obbsat::backend b : concrete) {
        if (obbsat::cpu_supports(b)) {
            runnable.push_back(b);
        } else {
            skipped << "obbsat_bench: skipping collide/*/*/" << obbsat::backend_name(b)
                    << "/*: not compiled in or not supported by this CPU\n";
        }
    }
    const batch_mode modes[] = {batch_mode::stream, batch_mode::indexed_sorted,
                                batch_mode::indexed_random};
    // The library may keep a small batch on one core whatever `threads` asks;
    // the 4K threads:2 rows show that choice rather than a second core.
    const unsigned thread_counts[] = {1, 2};

    for (const obbsat::method test : obbsat::methods_on(obbsat::store_kind::corners)) {
        for (const batch_mode mode : modes) {
            for (const obbsat::backend use : runnable) {
                for (const std::size_t pairs : grid_sizes) {
                    for (const unsigned threads : thread_counts) {
                        register_case({test, mode, use, pairs, threads,
                                       obbsat::scene_density::typical, rect_store::records});
                    }
                }
            }
        }
        // How the share of colliding pairs moves the rate (early exits,
        // branch prediction): the best backend and the scalar one.
        std::vector<obbsat::backend> density_backends = {obbsat::best_supported_backend()};
        if (density_backends.front() != obbsat::backend::scalar) {
            density_backends.push_back(obbsat::backend::scalar);
        }
        for (const obbsat::backend use : density_backends) {
            for (const obbsat::scene_density density :
                 {obbsat::scene_density::sparse, obbsat::scene_density::dense}) {
                for (const unsigned threads : thread_counts) {
                    register_case({test, batch_mode::indexed_sorted, use, density_variant_size,
                                   threads, density, rect_store::records});
                }
            }
        }
        // The structure-of-arrays store on the same pair lists, one core.
        for (const batch_mode mode : {batch_mode::indexed_sorted, batch_mode::indexed_random}) {
            for (const obbsat::backend use : runnable) {
                for (const std::size_t pairs : grid_sizes) {
                    register_case({test, mode, use, pairs, 1, obbsat::scene_density::typical,
                                   rect_store::soa});
                }
            }
        }
    }
    // The methods on poses, on pose stores built from the same scenes
    // (pose_records::from_corners), beside the corner rows above.
    for (const obbsat::method test : obbsat::methods_on(obbsat::store_kind::poses)) {
        for (const batch_mode mode : modes) {
            for (const obbsat::backend use : runnable) {
                for (const std::size_t pairs : grid_sizes) {
                    for (const unsigned threads : thread_counts) {
                        register_case({test, mode, use, pairs, threads, obbsat::scene_density::typical,
                                       rect_store::poses});
                    }
                }
            }
        }
        // Streams over pose_records (transposed in registers), one core.
        for (const obbsat::backend use : runnable) {
            for (const std::size_t pairs : grid_sizes) {
                register_case({test, batch_mode::stream, use, pairs, 1, obbsat::scene_density::typical,
                               rect_store::pose_records_stream});
            }
        }
        // Pair lists over rect_pose rows read in place (what Python's arrays
        // are), beside the same lists over pose_records.
        for (const batch_mode mode : {batch_mode::indexed_sorted, batch_mode::indexed_random}) {
            for (const obbsat::backend use : runnable) {
                for (const std::size_t pairs : grid_sizes) {
                    for (const unsigned threads : thread_counts) {
                        register_case({test, mode, use, pairs, threads, obbsat::scene_density::typical,
                                       rect_store::pose_rows});
                    }
                }
            }
        }
    }
}

}  // namespace obbsat_bench
