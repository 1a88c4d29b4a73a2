// obbsat demo: every backend this CPU runs, timed on one seeded scene, each
// run checked byte for byte against its reference before its time counts for
// anything. The scene's rectangles are timed in both corner stores and, for
// the methods on poses, in a pose store built from the same corners, so that
// a method on poses is read beside the corner test it stands in for.
#include "accuracy/accuracy_brief.hpp"
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "demo/demo_box2d.hpp"
#include "demo/demo_scene.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/ref/pose_corners.hpp>
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

using clock = std::chrono::steady_clock;

double seconds_since(clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
}

struct demo_settings {
    std::size_t rects = 100000;
    std::size_t pairs = 1000000;
    std::uint64_t seed = 1;
    scene_density density = scene_density::typical;
    const char* density_name = "typical";
    unsigned reps = 7;
    std::size_t scene_boxes = 0;  // the scene query's section: 0 leaves it out; by default 10 x rects
    // The article's test on corners, and beside it the same test on poses.
    std::vector<method> methods{method::sat4, method::local};
};

// One row of the table: a way to compute the scene's verdicts.
struct demo_entry {
    std::string runner;  // a backend's name, or whatever else computes the verdicts
    std::string store;   // how the rectangles are laid out in memory: soa, records or poses
    unsigned threads;
    std::function<void(std::uint8_t* verdicts)> run;
};

// The rows of one method on one kind of store, and the verdicts they must all
// reproduce: on corners the method on the scalar backend over soa at 1
// thread, on poses the method's scalar reference on poses called pair by pair.
struct demo_group {
    method test;
    store_kind kind;
    const char* reference_name;  // for the message when a row differs
    std::function<void(std::uint8_t* verdicts)> reference;
    std::vector<demo_entry> entries;  // the first is what 'speedup' compares against
};

// The scene, with its rectangles in every store the library takes for pair
// lists: arrays per coordinate, packed corner records (one cache line each),
// and packed poses (half a cache line each), built from the same corners.
struct demo_scene {
    scene world;
    rect_records records;
    pose_records poses;
};

// A row as measured, for the comparisons printed under the table.
struct measured_row {
    method test;
    std::string runner;
    std::string store;
    unsigned threads;
    double seconds;  // the median
};

const std::vector<option_spec>& demo_option_specs() {
    static const std::vector<option_spec> specs = {
        {"rects", "N", "rectangles in the scene (default: 100000)"},
        {"pairs", "N", "candidate pairs wanted (default: 1000000)"},
        {"seed", "S", "scene seed (default: 1)"},
        {"density", "D", "sparse, typical or dense: about 5%, 30% or 80% collide (default: typical)"},
        {"reps", "K", "timed repetitions per row, after one warm-up; the median counts (default: 7)"},
        {"scene-boxes", "N", "boxes in the scene query's section, 0 to leave it out (default: 10 x rects, 1000000)"},
        {"method", "NAME", "a collision test, or 'all' for every one this build offers (default: sat4 and local)"},
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
    s.scene_boxes = 10 * s.rects;
    if (const auto v = options.value("scene-boxes")) {
        s.scene_boxes = static_cast<std::size_t>(parse_number_option("scene-boxes", *v, 0, UINT32_MAX));
    }
    if (const auto v = options.value("method")) {
        if (*v == "all") {
            s.methods = all_methods();
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

// The corner test a method on poses is read beside: local is the article's
// test taken into A's frame, so it stands beside sat4; conservative and exact
// run on both kinds of store, so each stands beside itself.
method corner_counterpart(method m) { return m == method::local ? method::sat4 : m; }

// The method and store groups to time, in table order: by the declaration
// order of each method's corner counterpart, corners before poses.
std::vector<std::pair<method, store_kind>> group_order(const std::vector<method>& methods) {
    const std::vector<method> order = all_methods();
    const auto rank = [&order](method m) {
        return std::find(order.begin(), order.end(), corner_counterpart(m)) - order.begin();
    };
    std::vector<std::pair<method, store_kind>> groups;
    for (const method m : methods) {
        for (const store_kind kind : {store_kind::corners, store_kind::poses}) {
            if (runs_on(m, kind)) {
                groups.emplace_back(m, kind);
            }
        }
    }
    std::stable_sort(groups.begin(), groups.end(), [&rank](const auto& x, const auto& y) {
        return rank(x.first) < rank(y.first) ||
               (rank(x.first) == rank(y.first) && x.second == store_kind::corners &&
                y.second == store_kind::poses);
    });
    return groups;
}

collide_options options_for(method test, backend b, unsigned threads) {
    collide_options options;
    options.test = test;
    options.use = b;
    options.threads = threads;
    return options;
}

// Every group the demo times, each method's rows on corners first.
std::vector<demo_group> demo_groups(const demo_scene& demo, const std::vector<method>& methods) {
    std::vector<demo_group> groups;
    const std::vector<pair_index>& pairs = demo.world.pairs;
    for (const auto& [test, kind] : group_order(methods)) {
        demo_group group{test, kind, "", nullptr, {}};
        if (kind == store_kind::corners) {
            group.reference_name = "the scalar reference (the scalar backend over soa at 1 thread)";
            const collide_options reference = options_for(test, backend::scalar, 1);
            group.reference = [&demo, &pairs, reference](std::uint8_t* verdicts) {
                collide_pairs(demo.world.rects, pairs.data(), pairs.size(), verdicts, reference);
            };
            for (const char* store : {"soa", "records"}) {
                const bool soa = std::strcmp(store, "soa") == 0;
                for (const backend b : runnable_backends()) {
                    for (const unsigned threads : {1u, 2u}) {
                        const collide_options options = options_for(test, b, threads);
                        auto run = [&demo, &pairs, soa, options](std::uint8_t* verdicts) {
                            if (soa) {
                                collide_pairs(demo.world.rects, pairs.data(), pairs.size(), verdicts,
                                              options);
                            } else {
                                collide_pairs(demo.records, pairs.data(), pairs.size(), verdicts,
                                              options);
                            }
                        };
                        group.entries.push_back(demo_entry{backend_name(b), store, threads, run});
                    }
                }
            }
        } else {
            group.reference_name = "the scalar reference on poses (obbsat::pose_method_reference)";
            const pose_reference_fn reference = pose_method_reference(test);
            group.reference = [&demo, &pairs, reference](std::uint8_t* verdicts) {
                for (std::size_t i = 0; i < pairs.size(); ++i) {
                    verdicts[i] = reference(demo.poses[pairs[i].a], demo.poses[pairs[i].b]) ? 1 : 0;
                }
            };
            for (const backend b : runnable_backends()) {
                for (const unsigned threads : {1u, 2u}) {
                    const collide_options options = options_for(test, b, threads);
                    auto run = [&demo, &pairs, options](std::uint8_t* verdicts) {
                        collide_pairs(demo.poses, pairs.data(), pairs.size(), verdicts, options);
                    };
                    group.entries.push_back(demo_entry{backend_name(b), "poses", threads, run});
                }
            }
        }
        // ---- More rows for this method go here. --------------------------
        // A peer implementation (another library's test on the same scene) is
        // one more demo_entry with its own `runner` name and a `run` that
        // writes one 0/1 byte per pair of demo.world.pairs; it is then checked
        // against the group's reference and timed like every backend. Only add
        // rows that really run: every figure in the table is measured here.
        // -------------------------------------------------------------------
        groups.push_back(std::move(group));
    }
    return groups;
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

void print_mismatch(const demo_group& group, const demo_entry& entry, const scene& world,
                    const std::vector<std::uint8_t>& want, const std::vector<std::uint8_t>& got,
                    std::size_t at) {
    const pair_index& p = world.pairs[at];
    std::fprintf(stderr,
                 "obbsat: demo: %s on %s (%s, %u thread(s)) disagrees with %s at pair %zu "
                 "(rectangles %" PRIu32 " and %" PRIu32 "): verdict %u, reference %u\n",
                 method_name(group.test), entry.runner.c_str(), entry.store.c_str(), entry.threads,
                 group.reference_name, at, p.a, p.b, static_cast<unsigned>(got[at]),
                 static_cast<unsigned>(want[at]));
}

const measured_row* find_row(const std::vector<measured_row>& rows, method test, const char* store,
                             const char* runner, unsigned threads) {
    for (const measured_row& row : rows) {
        if (row.test == test && row.store == store && row.runner == runner && row.threads == threads) {
            return &row;
        }
    }
    return nullptr;
}

// Each method on poses against the corner test it stands in for, both over
// packed records of the same rectangles on the best backend at 1 thread.
void print_pose_ratios(const std::vector<measured_row>& rows, double pairs) {
    const char* best = backend_name(best_supported_backend());
    bool first = true;
    for (const measured_row& row : rows) {
        if (row.store != "poses" || row.runner != best || row.threads != 1) {
            continue;
        }
        const method counterpart = corner_counterpart(row.test);
        const measured_row* corners = find_row(rows, counterpart, "records", best, 1);
        if (corners == nullptr) {
            continue;
        }
        if (first) {
            std::printf("poses against corners (%s, 1 thread, the same pairs):\n", best);
            first = false;
        }
        std::printf("  %s on poses: %.1f Mpairs/s, %.2fx %s on records (%.1f Mpairs/s)\n",
                    method_name(row.test), pairs / row.seconds / 1e6, corners->seconds / row.seconds,
                    method_name(counterpart), pairs / corners->seconds / 1e6);
    }
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

// The median time of `reps` runs of `run` after one warm-up, or nothing when
// `check`, called after every run, returns false; `prepare` runs before each
// run, untimed.
template <class Prepare, class Run, class Check>
std::optional<double> timed_median(unsigned reps, Prepare prepare, Run run, Check check) {
    std::vector<double> times;
    for (unsigned rep = 0; rep <= reps; ++rep) {
        prepare();
        const clock::time_point start = clock::now();
        run();
        const double elapsed = seconds_since(start);
        if (!check()) {
            return std::nullopt;
        }
        if (rep > 0) {  // rep 0 is the warm-up
            times.push_back(elapsed);
        }
    }
    return median_of(times);
}

// Getting a scene's poses into corners for a corner method: the SIMD
// conversion of rotation-vector poses (convert_to_corners into the caller's
// buffer, every backend, each run checked byte for byte against
// ref::corners_of) against corners built from angles (rect_records::from_poses:
// cos and sin in double per box, into a new checked store). Returns false
// after a message when a conversion differs from the reference.
bool print_conversions(const demo_scene& demo, unsigned reps) {
    const pose_records& poses = demo.poses;
    const std::size_t count = poses.size();
    std::vector<rect> want(count);
    for (std::size_t i = 0; i < count; ++i) {
        want[i] = ref::corners_of(poses[i]);
    }
    std::vector<pose> angles(count);
    for (std::size_t i = 0; i < count; ++i) {
        angles[i] = pose_of(demo.records[i]);
    }
    const double boxes = static_cast<double>(count);
    const std::optional<double> from_angles = timed_median(
        reps, [] {}, [&angles] { rect_records built = rect_records::from_poses(angles); (void)built; },
        [] { return true; });
    std::printf("\nposes to corners, %zu boxes, median of %u runs after one warm-up:\n", count, reps);
    std::printf("  %-16s  %-24s  %-8s  %8s  %9s\n", "pose", "conversion", "backend", "ns/box", "speedup");
    std::printf("  %-16s  %-24s  %-8s  %8.2f  %8.2fx\n", "angle", "rect_records::from_poses", "-",
                *from_angles / boxes * 1e9, 1.0);
    // Filled with NaN bytes before each run, so that a corner a run did not
    // write cannot pass for the reference's.
    std::vector<rect> got(count);
    const auto poison = [&got] { std::memset(static_cast<void*>(got.data()), 0xff, got.size() * sizeof(rect)); };
    for (const backend b : runnable_backends()) {
        std::size_t differs = count;
        const std::optional<double> seconds = timed_median(
            reps, poison, [&] { convert_to_corners(poses, got.data(), b); },
            [&] {
                for (std::size_t i = 0; i < count; ++i) {
                    if (std::memcmp(&got[i], &want[i], sizeof(rect)) != 0) {
                        differs = i;
                        return false;
                    }
                }
                return true;
            });
        if (!seconds) {
            std::fprintf(stderr,
                         "obbsat: demo: convert_to_corners on %s gives other corners than ref::corners_of "
                         "for pose %zu\n",
                         backend_name(b), differs);
            return false;
        }
        std::printf("  %-16s  %-24s  %-8s  %8.2f  %8.2fx\n", "rotation vector", "convert_to_corners",
                    backend_name(b), *seconds / boxes * 1e9, *from_angles / *seconds);
    }
    std::printf("every convert_to_corners run gave the corners of ref::corners_of, byte for byte; speedup\n"
                "against corners built from angles (cos and sin in double per box, into a new checked store)\n\n");
    return true;
}

}  // namespace

void print_demo_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat demo [--rects N] [--pairs N] [--seed S] [--density D] [--reps K]\n"
                 "                   [--method NAME|all]\n"
                 "\n"
                 "Builds a seeded broadphase-like scene and runs method sat4 and, beside it,\n"
                 "method local on the same rectangles as poses (or the --method given, on every\n"
                 "store it runs on) on every backend this CPU runs, at 1 and 2 threads. Corners\n"
                 "are timed in both corner stores (soa: one array per coordinate; records: one\n"
                 "packed 32-byte record per rectangle), poses in a pose store built from the\n"
                 "same corners (poses: one packed 32-byte record per pose). Every run's verdicts\n"
                 "are checked byte for byte against the method's reference: on corners the\n"
                 "scalar backend over soa at 1 thread, on poses the scalar reference on poses\n"
                 "(exit status 1 if any differs). Prints throughput, speedup over the first row\n"
                 "of each method and store, the verdict digest (FNV-1a) and the share of pairs\n"
                 "that collide; then each method on poses against its corner counterpart, the\n"
                 "conversion of poses to corners (every backend, checked against the reference)\n"
                 "against corners built from angles, Box2D on the same pairs, the accuracy\n"
                 "summary, and the scene query: a million poses (--scene-boxes) to every\n"
                 "colliding pair, cold and frame after frame, uniform and mixed sizes, at 1 and\n"
                 "2 threads, each stage timed, beside Box2D's broadphase and narrowphase on a\n"
                 "scene of 100000 boxes.\n"
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

    const clock::time_point build_start = clock::now();
    demo_scene demo;
    demo.world = make_scene(
        scene_spec_for(settings.density, settings.rects, settings.pairs, settings.seed));
    demo.records = records_of(demo.world.rects);
    demo.poses = pose_records::from_corners(demo.records);
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
                "byte against the reference,\non corners the same method on the scalar backend over "
                "soa at 1 thread, on poses the method's scalar\nreference on poses (the poses are "
                "built from the same corners); 'speedup' compares against the first\nrow of each "
                "method and store\n\n",
                settings.reps);
    int method_width = static_cast<int>(std::strlen("method"));
    for (const method m : settings.methods) {
        method_width = std::max(method_width, static_cast<int>(std::strlen(method_name(m))));
    }
    std::printf("%-*s  %-8s  %-7s  %7s  %9s  %8s  %8s  %-16s  %9s\n", method_width, "method",
                "backend", "store", "threads", "Mpairs/s", "ns/pair", "speedup", "digest",
                "colliding");
    std::fflush(stdout);

    const std::vector<demo_group> groups = demo_groups(demo, settings.methods);
    const std::string best = backend_name(best_supported_backend());
    const double pairs = static_cast<double>(count);
    std::vector<std::uint8_t> reference(count);
    std::vector<std::uint8_t> verdicts(count);
    std::vector<measured_row> measured;
    std::vector<accuracy::timed_method> timed;  // for the accuracy lines below
    std::vector<std::uint8_t> sat4_verdicts;    // for the Box2D comparison below
    for (const demo_group& group : groups) {
        group.reference(reference.data());
        if (group.test == method::sat4 && group.kind == store_kind::corners) {
            sat4_verdicts = reference;
        }
        double baseline_seconds = 0.0;
        for (const demo_entry& entry : group.entries) {
            std::size_t at = count;
            const std::optional<double> seconds = timed_median(
                settings.reps, [&] { std::fill(verdicts.begin(), verdicts.end(), std::uint8_t{0xff}); },
                [&] { entry.run(verdicts.data()); },
                [&] {
                    at = first_difference(reference, verdicts);
                    return at == count;
                });
            if (!seconds) {
                print_mismatch(group, entry, world, reference, verdicts, at);
                return exit_internal_error;
            }
            if (baseline_seconds == 0.0) {
                baseline_seconds = *seconds;
            }
            measured.push_back({group.test, entry.runner, entry.store, entry.threads, *seconds});
            if (entry.store == "records" && entry.threads == 1 && entry.runner == best) {
                timed.push_back({group.test, pairs / *seconds / 1e6});
            }
            const std::uint64_t digest = verdict_digest(verdicts.data(), count);
            const auto colliding = std::count(verdicts.begin(), verdicts.end(), std::uint8_t{1});
            std::printf("%-*s  %-8s  %-7s  %7u  %9.1f  %8.2f  %7.2fx  %016" PRIx64 "  %8.2f%%\n",
                        method_width, method_name(group.test), entry.runner.c_str(), entry.store.c_str(),
                        entry.threads, pairs / *seconds / 1e6, *seconds / pairs * 1e9,
                        baseline_seconds / *seconds, digest,
                        100.0 * static_cast<double>(colliding) / pairs);
            std::fflush(stdout);
        }
    }
    std::printf("\nall %zu rows agree with the scalar reference of their method and store (best backend "
                "here: %s)\n",
                measured.size(), best.c_str());
    print_pose_ratios(measured, pairs);
    if (!print_conversions(demo, settings.reps)) {
        return exit_internal_error;
    }
    double best_sat4_seconds[2] = {0.0, 0.0};  // best backend, records, 1 and 2 threads
    for (unsigned t = 1; t <= 2; ++t) {
        if (const measured_row* row = find_row(measured, method::sat4, "records", best.c_str(), t)) {
            best_sat4_seconds[t - 1] = row->seconds;
        }
    }
    print_box2d_comparison(world, settings.reps, sat4_verdicts, best_sat4_seconds);
    accuracy::print_accuracy_brief(stdout, timed);
    if (settings.scene_boxes >= 2) {
        scene_demo_settings scene;
        scene.boxes = settings.scene_boxes;
        scene.seed = settings.seed;
        scene.reps = std::min(settings.reps, 3u);
        if (!print_scene_queries(scene)) {
            return exit_internal_error;
        }
    }
    return exit_success;
}

}  // namespace obbsat::cli
