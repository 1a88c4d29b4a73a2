#include "scene_harness.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <string>
#include <utility>

namespace obbsat_bench {

namespace {

bool pair_less(const obbsat::pair_index& x, const obbsat::pair_index& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
}

/// What the check before timing found, kept across Google Benchmark's calls
/// of one row (it enters a row several times: to size the iteration count,
/// then once per repetition).
struct row_check {
    bool done = false;
    std::string error;
    pair_set_difference difference;
};

const char* frame_name(scene_frame f) {
    return f == scene_frame::as_generated ? "as generated" : "moved";
}

/// Runs the query on the frames a row is checked on and compares each answer
/// with the reference; fills `check.error` when an exact query differs.
void check_row(scene_workload& w, const scene_rows& rows, scene_row_kind kind, unsigned threads,
               const scene_query_factory& make, row_check& check) {
    const std::vector<scene_frame> frames =
        kind == scene_row_kind::frame ? std::vector<scene_frame>{scene_frame::as_generated, scene_frame::moved,
                                             scene_frame::as_generated}
                  : std::vector<scene_frame>{scene_frame::as_generated};
    const std::unique_ptr<scene_query> query = make(threads);
    for (const scene_frame f : frames) {
        const std::vector<obbsat::pair_index>& expected =
            w.reference_pairs(f, rows.expected.store, rows.expected.test);
        const pair_set_difference d = compare_pair_sets(query->find(f), expected);
        check.difference.both += d.both;
        check.difference.only_found += d.only_found;
        check.difference.only_expected += d.only_expected;
        if (rows.expected.must_match && (d.only_found != 0 || d.only_expected != 0) && check.error.empty()) {
            check.error = std::to_string(d.only_found + d.only_expected) + " pairs of the " + frame_name(f) +
                          " frame differ from the reference of " + obbsat::method_name(rows.expected.test) +
                          " on " + obbsat::store_name(rows.expected.store) + " (" +
                          std::to_string(d.only_found) + " reported only here, " +
                          std::to_string(d.only_expected) + " only in the reference, " + std::to_string(d.both) +
                          " in both)";
        }
    }
    check.done = true;
}

struct totals {
    double pairs = 0;
    double candidates = 0;
    double reused = 0;
    bool reports_order = false;
    double kernel_seconds = 0;
    bool reports_kernel = false;

    void add(const scene_query& query, std::size_t pairs_found) {
        pairs += static_cast<double>(pairs_found);
        candidates += static_cast<double>(query.candidates());
        if (const std::optional<bool> reused_order = query.reused_order()) {
            reports_order = true;
            reused += *reused_order ? 1.0 : 0.0;
        }
        if (const std::optional<double> kernel = query.kernel_seconds()) {
            reports_kernel = true;
            kernel_seconds += *kernel;
        }
    }
};

void set_counters(benchmark::State& state, std::size_t boxes, const totals& sum, const row_check& check) {
    const auto n = static_cast<double>(boxes);
    // Rate of (boxes * 1e-9) per second, inverted: nanoseconds per box.
    state.counters["ns_per_box"] =
        benchmark::Counter(n * 1e-9, static_cast<benchmark::Counter::Flags>(
                                         benchmark::Counter::kIsIterationInvariantRate |
                                         benchmark::Counter::kInvert));
    state.counters["pairs_per_box"] = benchmark::Counter(sum.pairs / n, benchmark::Counter::kAvgIterations);
    state.counters["candidates_per_box"] =
        benchmark::Counter(sum.candidates / n, benchmark::Counter::kAvgIterations);
    if (sum.reports_order) {
        state.counters["reused_order"] = benchmark::Counter(sum.reused, benchmark::Counter::kAvgIterations);
    }
    if (sum.reports_kernel && sum.candidates > 0) {
        state.counters["kernel_ns_per_candidate"] = sum.kernel_seconds * 1e9 / sum.candidates;
    }
    if (check.done) {
        const pair_set_difference& d = check.difference;
        const double all = static_cast<double>(std::max<std::size_t>(1, d.both + d.only_found + d.only_expected));
        state.counters["agreement"] = static_cast<double>(d.both) / all;
        state.counters["peer_only"] = static_cast<double>(d.only_found) / all;
        state.counters["reference_only"] = static_cast<double>(d.only_expected) / all;
    }
}

void run_row(benchmark::State& state, const scene_rows& rows, scene_row_kind kind, std::size_t boxes,
             obbsat::scene_sizes sizes, unsigned threads, row_check& check) {
    totals sum;
    try {
        scene_workload& w = scene_workload_for(boxes, sizes);
        // Built now, so that no timed call pays for building the moved frame.
        w.poses(scene_frame::moved);
        const scene_query_factory make = rows.prepare(w, kind);
        if (!check.done && boxes <= check_limit) {
            check_row(w, rows, kind, threads, make, check);
        }
        if (!check.error.empty()) {
            state.SkipWithError(check.error.c_str());
            return;
        }
        if (kind == scene_row_kind::frame) {
            // The first finds build what the query keeps and grow its buffers
            // (a pair_finder keeps nothing at its first call, keeps the pairs
            // of widened bounds at its second, and answers from them from its
            // third): two rounds of both frames, untimed; the timed finds
            // alternate frames from there, as a simulation's steps would.
            const std::unique_ptr<scene_query> query = make(threads);
            scene_frame next = scene_frame::moved;
            for (int warm = 0; warm < 4; ++warm) {
                next = other_frame(next);
                query->find(next);
            }
            for (auto _ : state) {
                next = other_frame(next);
                const std::vector<obbsat::pair_index>& pairs = query->find(next);
                benchmark::DoNotOptimize(pairs.data());
                sum.add(*query, pairs.size());
            }
        } else {
            for (auto _ : state) {
                const std::unique_ptr<scene_query> query = make(threads);
                const std::vector<obbsat::pair_index>& pairs = query->find(scene_frame::as_generated);
                benchmark::DoNotOptimize(pairs.data());
                sum.add(*query, pairs.size());
            }
        }
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    set_counters(state, boxes, sum, check);
}

}  // namespace

std::vector<std::size_t> register_scene_rows(const scene_rows& rows) {
    std::vector<std::size_t> left_out;
    for (const std::size_t boxes : scene_box_counts_to_register()) {
        if (boxes > rows.max_boxes) {
            left_out.push_back(boxes);
        }
    }
    for (const scene_row_kind kind : {scene_row_kind::cold, scene_row_kind::frame}) {
        for (const std::size_t boxes : scene_box_counts_to_register()) {
            if (boxes > rows.max_boxes) {
                continue;
            }
            for (const obbsat::scene_sizes sizes : scene_size_spreads) {
                for (const unsigned threads : rows.thread_counts) {
                    const std::string name =
                        (kind == scene_row_kind::frame ? rows.frame_prefix : rows.cold_prefix) + "/" +
                                             scene_name_tail(boxes, sizes, threads);
                    auto check = std::make_shared<row_check>();
                    // Real time: with threads > 1 the work runs on other
                    // cores too, whose CPU time this thread never sees.
                    benchmark::RegisterBenchmark(name.c_str(),
                                                 [rows, kind, boxes, sizes, threads,
                                                  check](benchmark::State& state) {
                                                     run_row(state, rows, kind, boxes, sizes, threads, *check);
                                                 })
                        ->UseRealTime()
                        ->Unit(benchmark::kMillisecond);
                }
            }
        }
    }
    return left_out;
}

pair_set_difference compare_pair_sets(std::vector<obbsat::pair_index> found,
                                      std::vector<obbsat::pair_index> expected) {
    std::sort(found.begin(), found.end(), pair_less);
    std::sort(expected.begin(), expected.end(), pair_less);
    pair_set_difference d;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < found.size() || j < expected.size()) {
        if (j == expected.size() || (i < found.size() && pair_less(found[i], expected[j]))) {
            ++d.only_found;
            ++i;
        } else if (i == found.size() || pair_less(expected[j], found[i])) {
            ++d.only_expected;
            ++j;
        } else {
            ++d.both;
            ++i;
            ++j;
        }
    }
    return d;
}

}  // namespace obbsat_bench
