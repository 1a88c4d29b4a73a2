// obbsat demo: every backend this CPU runs, timed on one seeded scene, each
// run checked byte for byte against the scalar reference before its time
// counts for anything.
#include "accuracy_brief.hpp"
#include "cli_args.hpp"
#include "commands.hpp"
#include "demo_box2d.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace obbsat::cli {

namespace {

struct demo_settings {
    std::size_t rects = 100000;
    std::size_t pairs = 1000000;
    std::uint64_t seed = 1;
    scene_density density = scene_density::typical;
    const char* density_name = "typical";
    unsigned reps = 7;
    std::vector<method> methods{method::sat4};
};

// One row of the table: a way to compute the scene's verdicts.
struct demo_entry {
    method test;
    std::string runner;  // a backend's name, or whatever else computes the verdicts
    std::string store;   // how the rectangles are laid out in memory
    unsigned threads;
    std::function<void(std::uint8_t* verdicts)> run;
    bool is_reference;   // the row the others are checked and compared against
};

// The scene, with its rectangles in both stores the library takes for pair
// lists: arrays per coordinate, and packed records (one cache line each).
struct demo_scene {
    scene world;
    rect_records records;
};

struct demo_result {
    double median_seconds;
    std::uint64_t digest;
    std::size_t colliding;
};

const std::vector<option_spec>& demo_option_specs() {
    static const std::vector<option_spec> specs = {
        {"rects", "N", "rectangles in the scene (default: 100000)"},
        {"pairs", "N", "candidate pairs wanted (default: 1000000)"},
        {"seed", "S", "scene seed (default: 1)"},
        {"density", "D", "sparse, typical or dense: about 5%, 30% or 80% collide (default: typical)"},
        {"reps", "K", "timed repetitions per row, after one warm-up; the median counts (default: 7)"},
        {"method", "NAME", "a collision test, or 'all' for every one this build offers (default: sat4)"},
        {"help", "", "show this help"},
    };
    return specs;
}

demo_settings settings_from(const parsed_options& options) {
    demo_settings s;
    if (const auto v = options.value("rects")) {
        s.rects = static_cast<std::size_t>(parse_number_option("rects", *v, 2, UINT32_MAX));
    }
    if (const auto v = options.value("pairs")) {
        s.pairs = static_cast<std::size_t>(parse_number_option("pairs", *v, 1, 1000000000));
    }
    if (const auto v = options.value("seed")) {
        s.seed = parse_number_option("seed", *v, 0, UINT64_MAX);
    }
    if (const auto v = options.value("reps")) {
        s.reps = static_cast<unsigned>(parse_number_option("reps", *v, 1, 1000));
    }
    if (const auto v = options.value("method")) {
        if (*v == "all") {
            s.methods = methods_on(store_kind::corners);
        } else if (const auto m = parse_method(*v)) {
            s.methods = {*m};
        } else {
            throw usage_error("--method: expected " + method_list() + ", or all, got '" + std::string(*v) +
                              "'");
        }
    }
    if (const auto v = options.value("density")) {
        if (*v == "sparse") {
            s.density = scene_density::sparse;
            s.density_name = "sparse";
        } else if (*v == "typical") {
            s.density = scene_density::typical;
            s.density_name = "typical";
        } else if (*v == "dense") {
            s.density = scene_density::dense;
            s.density_name = "dense";
        } else {
            throw usage_error("--density: expected sparse, typical or dense, got '" +
                              std::string(*v) + "'");
        }
    }
    return s;
}

rect_records records_of(const rect_soa& rects) {
    std::vector<rect> plain;
    plain.reserve(rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        plain.push_back(rects[i]);
    }
    return rect_records(plain);
}

// The backends this CPU runs: scalar first, then narrowest to widest.
std::vector<backend> runnable_backends() {
    std::vector<backend> runnable{backend::scalar};
    const std::vector<backend> compiled = compiled_backends();  // best first
    for (auto b = compiled.rbegin(); b != compiled.rend(); ++b) {
        if (*b != backend::scalar && cpu_supports(*b)) {
            runnable.push_back(*b);
        }
    }
    return runnable;
}

// Box2D's narrow phase on the same pairs, and the speedup of the best sat4
// rows over it; `sat4_seconds` holds the best backend's records rows at 1
// and 2 threads (0 where not timed).
void print_box2d_comparison(const scene& world, unsigned reps, const std::vector<std::uint8_t>& sat4,
                            const double sat4_seconds[2]) {
    if (sat4.empty()) {
        return;
    }
    const std::optional<peer_timing> box2d = time_box2d(world.rects, world.pairs, reps, sat4);
    if (!box2d) {
        std::printf("Box2D: not found when this program was built (Debian: libbox2d-dev); no peer comparison\n");
        return;
    }
    const double pairs = static_cast<double>(world.pairs.size());
    std::printf("Box2D 2.4 b2CollidePolygons, 1 thread: %.1f Mpairs/s (%.2f ns/pair), same verdict as sat4 "
                "on %.2f%% of pairs\n",
                pairs / box2d->median_seconds / 1e6, box2d->median_seconds / pairs * 1e9,
                100.0 * box2d->agreement);
    for (unsigned t = 0; t < 2; ++t) {
        if (sat4_seconds[t] > 0.0) {
            std::printf("  sat4 %s records, %u thread%s: %.1fx Box2D\n", backend_name(best_supported_backend()),
                        t + 1, t == 0 ? "" : "s", box2d->median_seconds / sat4_seconds[t]);
        }
    }
}

// Every row the demo times, the reference of each method first.
std::vector<demo_entry> demo_entries(const demo_scene& demo, const std::vector<method>& methods) {
    std::vector<demo_entry> entries;
    const std::vector<pair_index>& pairs = demo.world.pairs;
    for (const method test : methods) {
        for (const char* store : {"soa", "records"}) {
            const bool soa = std::strcmp(store, "soa") == 0;
            for (const backend b : runnable_backends()) {
                for (const unsigned threads : {1u, 2u}) {
                    collide_options options;
                    options.test = test;
                    options.use = b;
                    options.threads = threads;
                    auto run = [&demo, &pairs, soa, options](std::uint8_t* verdicts) {
                        if (soa) {
                            collide_pairs(demo.world.rects, pairs.data(), pairs.size(), verdicts,
                                          options);
                        } else {
                            collide_pairs(demo.records, pairs.data(), pairs.size(), verdicts,
                                          options);
                        }
                    };
                    entries.push_back(demo_entry{test, backend_name(b), store, threads, run,
                                                 soa && b == backend::scalar && threads == 1});
                }
            }
        }
        // ---- More rows for this method go here. --------------------------
        // A peer implementation (another library's test on the same scene) is
        // one more demo_entry with its own `runner` name and a `run` that
        // writes one 0/1 byte per pair of demo.world.pairs; it is then checked
        // against the reference and timed like every backend. Only add rows
        // that really run: every figure in the table is measured here.
        // -------------------------------------------------------------------
    }
    return entries;
}

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

// The first pair where `got` differs from `want`, or count if none does.
std::size_t first_difference(const std::vector<std::uint8_t>& want,
                             const std::vector<std::uint8_t>& got) {
    const auto [a, b] = std::mismatch(want.begin(), want.end(), got.begin());
    (void)b;
    return static_cast<std::size_t>(a - want.begin());
}

void print_mismatch(const demo_entry& entry, const scene& world,
                    const std::vector<std::uint8_t>& want, const std::vector<std::uint8_t>& got,
                    std::size_t at) {
    const pair_index& p = world.pairs[at];
    std::fprintf(stderr,
                 "obbsat: demo: %s on %s (%s, %u thread(s)) disagrees with the scalar reference "
                 "at pair %zu (rectangles %" PRIu32 " and %" PRIu32 "): verdict %u, reference %u\n",
                 method_name(entry.test), entry.runner.c_str(), entry.store.c_str(),
                 entry.threads, at, p.a, p.b,
                 static_cast<unsigned>(got[at]), static_cast<unsigned>(want[at]));
}

}  // namespace

void print_demo_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat demo [--rects N] [--pairs N] [--seed S] [--density D] [--reps K]\n"
                 "                   [--method NAME|all]\n"
                 "\n"
                 "Builds a seeded broadphase-like scene, runs method sat4 (or the --method\n"
                 "given) on every backend this CPU runs, at 1 and 2 threads, over both rectangle\n"
                 "stores (soa: one array per coordinate; records: one packed 32-byte record per\n"
                 "rectangle), and checks every run's verdicts byte for byte against the same\n"
                 "method on the scalar backend over soa at 1 thread (exit status 1 if any\n"
                 "differs). Prints throughput, speedup over that reference, the verdict digest\n"
                 "(FNV-1a) and the share of pairs that collide.\n"
                 "\n"
                 "options:\n");
    print_options(out, demo_option_specs());
    std::fprintf(out,
                 "\n"
                 "example:\n"
                 "  obbsat demo --density dense --seed 7 --reps 11\n"
                 "  obbsat demo --method all --rects 20000 --pairs 200000\n");
}

int run_demo(const arguments& args) {
    const demo_settings settings = settings_from(parse_options(args, demo_option_specs()));
    using clock = std::chrono::steady_clock;
    auto seconds_since = [](clock::time_point start) {
        return std::chrono::duration<double>(clock::now() - start).count();
    };

    const clock::time_point build_start = clock::now();
    demo_scene demo;
    demo.world = make_scene(
        scene_spec_for(settings.density, settings.rects, settings.pairs, settings.seed));
    demo.records = records_of(demo.world.rects);
    const double build_seconds = seconds_since(build_start);
    const scene& world = demo.world;
    const std::size_t count = world.pairs.size();
    if (count == 0) {
        throw usage_error("the scene has no candidate pairs; give it more --rects");
    }

    std::printf("obbsat %s demo: %zu rectangles, %zu candidate pairs (%s density, seed %" PRIu64
                "), built in %.2f s\n",
                OBBSAT_VERSION, world.rects.size(), count, settings.density_name, settings.seed,
                build_seconds);
    std::printf("each row: median of %u timed runs after one warm-up; every run checked byte for "
                "byte against the reference,\nthe same method on the scalar backend over soa at "
                "1 thread, which 'speedup' compares against\n\n",
                settings.reps);
    int method_width = static_cast<int>(std::strlen("method"));
    for (const method m : settings.methods) {
        method_width = std::max(method_width, static_cast<int>(std::strlen(method_name(m))));
    }
    std::printf("%-*s  %-8s  %-7s  %7s  %9s  %8s  %8s  %-16s  %9s\n", method_width, "method",
                "backend", "store", "threads", "Mpairs/s", "ns/pair", "speedup", "digest",
                "colliding");
    std::fflush(stdout);

    const std::vector<demo_entry> entries = demo_entries(demo, settings.methods);
    std::vector<std::uint8_t> reference;
    double reference_seconds = 0.0;
    std::vector<std::uint8_t> verdicts(count);
    std::vector<accuracy::timed_method> timed;  // for the accuracy lines below
    std::vector<std::uint8_t> sat4_verdicts;    // for the Box2D comparison below
    double best_sat4_seconds[2] = {0.0, 0.0};   // best backend, records, 1 and 2 threads
    for (const demo_entry& entry : entries) {
        if (entry.is_reference) {
            reference.assign(count, 0);
            entry.run(reference.data());
        }
        std::vector<double> times;
        for (unsigned rep = 0; rep <= settings.reps; ++rep) {
            std::fill(verdicts.begin(), verdicts.end(), std::uint8_t{0xff});
            const clock::time_point start = clock::now();
            entry.run(verdicts.data());
            const double elapsed = seconds_since(start);
            const std::size_t at = first_difference(reference, verdicts);
            if (at != count) {
                print_mismatch(entry, world, reference, verdicts, at);
                return exit_internal_error;
            }
            if (rep > 0) {  // rep 0 is the warm-up
                times.push_back(elapsed);
            }
        }
        demo_result result{median_of(times), verdict_digest(verdicts.data(), count),
                           static_cast<std::size_t>(
                               std::count(verdicts.begin(), verdicts.end(), std::uint8_t{1}))};
        if (entry.is_reference) {
            reference_seconds = result.median_seconds;
        }
        const double pairs = static_cast<double>(count);
        if (entry.store == "records" && entry.threads == 1 &&
            entry.runner == backend_name(best_supported_backend())) {
            timed.push_back({entry.test, pairs / result.median_seconds / 1e6});
        }
        if (entry.test == method::sat4 && entry.is_reference) {
            sat4_verdicts = verdicts;
        }
        if (entry.test == method::sat4 && entry.store == "records" && entry.threads <= 2 &&
            entry.runner == backend_name(best_supported_backend())) {
            best_sat4_seconds[entry.threads - 1] = result.median_seconds;
        }
        std::printf("%-*s  %-8s  %-7s  %7u  %9.1f  %8.2f  %7.2fx  %016" PRIx64 "  %8.2f%%\n",
                    method_width, method_name(entry.test), entry.runner.c_str(), entry.store.c_str(),
                    entry.threads,
                    pairs / result.median_seconds / 1e6, result.median_seconds / pairs * 1e9,
                    reference_seconds / result.median_seconds, result.digest,
                    100.0 * static_cast<double>(result.colliding) / pairs);
        std::fflush(stdout);
    }
    std::printf("\nall %zu rows agree with the scalar reference (best backend here: %s)\n",
                entries.size(), backend_name(best_supported_backend()));
    print_box2d_comparison(world, settings.reps, sat4_verdicts, best_sat4_seconds);
    accuracy::print_accuracy_brief(stdout, timed);
    return exit_success;
}

}  // namespace obbsat::cli
