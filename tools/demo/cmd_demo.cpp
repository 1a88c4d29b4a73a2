// obbsat demo: every backend this CPU runs, timed on one seeded scene, each
// run checked byte for byte against its reference before its time counts for
// anything. The scene's rectangles are timed in both corner stores and, for
// the methods on poses, in a pose store built from the same corners, so that
// a method on poses is read beside the corner test it stands in for.
#include "accuracy/accuracy_brief.hpp"
#include "cli/cli_args.hpp"
#include "cli/commands.hpp"
#include "demo/demo_comparisons.hpp"
#include "demo/demo_rows.hpp"
#include "demo/demo_scene.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/digest.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <cinttypes>
#include <cstring>
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
    std::size_t scene_boxes = 0;  // the scene query's section, any size: 0 leaves it out; by default 10 x rects
    // The article's test on corners, and beside it the same test on poses.
    std::vector<method> methods{method::sat4, method::local};
};

const std::vector<option_spec>& demo_option_specs() {
    static const std::vector<option_spec> specs = {
        {"rects", "N", "rectangles in the scene (default: 100000)"},
        {"pairs", "N", "candidate pairs wanted (default: 1000000)"},
        {"seed", "S", "scene seed (default: 1)"},
        {"density", "D", "sparse, typical or dense: about 5%, 30% or 80% collide (default: typical)"},
        {"reps", "K", "timed repetitions per row, after one warm-up; the median counts (default: 7)"},
        {"scene-boxes", "N",
         "boxes in the scene query's section, 0 to 4294967295; 0 leaves it out (default: 10 x rects, at most 4294967295; 1000000)"},
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
    s.scene_boxes = std::min<std::size_t>(10 * s.rects, UINT32_MAX);  // the option's own range
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

}  // namespace

void print_demo_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat demo [--rects N] [--pairs N] [--seed S] [--density D] [--reps K]\n"
                 "                   [--method NAME|all] [--scene-boxes N]\n"
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

    const demo_clock::time_point build_start = demo_clock::now();
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
    if (settings.scene_boxes > 0) {  // one box is a scene too: it has no pairs
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
