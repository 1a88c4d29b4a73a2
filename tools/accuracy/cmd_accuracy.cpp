// obbsat accuracy: every method on every hard-case family of its store (the
// methods on corners on the corner families, the methods on poses on the pose
// families), scored against the exact oracle, next to every method's speed;
// tables on stdout, and on request the figures as JSON and a speed-against-
// error plot as SVG.
#include "accuracy/accuracy_commands.hpp"
#include "accuracy/accuracy_json.hpp"
#include "accuracy/accuracy_report.hpp"
#include "accuracy/accuracy_text.hpp"
#include "accuracy/double_accuracy_report.hpp"
#include "accuracy/double_accuracy_text.hpp"
#include "accuracy/double_families.hpp"
#include "cli/cli_args.hpp"
#include "draw/accuracy_svg.hpp"
#include "io/atomic_output.hpp"

#include <obbsat/suites/family.hpp>
#include <obbsat/suites/pose_family.hpp>

#include <cinttypes>
#include <memory>
#include <string>

#include <unistd.h>

#ifndef OBBSAT_VERSION
#error "OBBSAT_VERSION must be defined by the build (the CMake project version)"
#endif

namespace obbsat::cli {

namespace {

const std::vector<option_spec>& accuracy_option_specs() {
    static const std::vector<option_spec> specs = {
        {"pairs", "N", "pairs per family and per pose family (default: 20000)"},
        {"seed", "S", "suite seed (default: 1)"},
        {"threads", "T", "cores for the oracle and the scored verdicts, 0 for all (default: 1)"},
        {"reps", "K", "timed runs per method after a warm-up; the median counts (default: 11)"},
        {"json", "FILE", "also write every figure as JSON, all or nothing"},
        {"svg", "FILE", "also write the speed-against-error plot as SVG, all or nothing"},
        {"precision", "P", "float (default) or double: the double methods on the double families"},
        {"help", "", "show this help"},
    };
    return specs;
}

std::unique_ptr<io::atomic_output> output_for(const parsed_options& options, const char* name) {
    const auto path = output_option(options, name);
    if (!path) {
        return nullptr;
    }
    return std::make_unique<io::atomic_output>(std::string(*path));
}

void write_whole(io::atomic_output& out, const std::string& text) {
    out.write(text.data(), text.size());
    out.commit();
}

// The progress line on a terminal, after each family.
accuracy::progress_fn family_progress(const char* then) {
    const bool show = ::isatty(STDERR_FILENO) == 1;
    return [show, then](std::size_t done, std::size_t total) {
        if (show) {
            std::fprintf(stderr, "\rscored %zu of %zu families", done, total);
            if (done == total) {
                std::fprintf(stderr, "%s\n", then);
            }
        }
    };
}

int run_double_accuracy(const accuracy::accuracy_settings& settings, io::atomic_output* json,
                        io::atomic_output* svg) {
    std::printf("obbsat %s accuracy --precision double: %zu pairs per family, %zu double pose families and "
                "%zu double corner families, seed %" PRIu64 ", %u scoring thread(s)\n",
                OBBSAT_VERSION, settings.pairs_per_family, accuracy::double_pose_family_names().size(),
                accuracy::double_corner_family_names().size(), settings.seed, settings.threads);
    std::printf("FP: said collide, truth separated; FN touch / FN overlap: said separated, truth "
                "touching / overlapping\n");
    std::fflush(stdout);
    const accuracy::double_accuracy_report report =
        accuracy::measure_double_accuracy(settings, family_progress(""));
    std::printf("verdicts on the %s backend (the fastest this CPU runs); cpu: %s\n\n",
                backend_name(report.used), report.cpu.c_str());
    accuracy::print_double_report(stdout, report);
    if (json != nullptr || svg != nullptr) {
        const accuracy::accuracy_report plotted = accuracy::plotted_report(report);
        if (json != nullptr) {
            write_whole(*json, accuracy::accuracy_json(plotted, OBBSAT_VERSION));
        }
        if (svg != nullptr) {
            write_whole(*svg, accuracy::accuracy_svg(plotted));
        }
    }
    return exit_success;
}

}  // namespace

void print_accuracy_help(std::FILE* out) {
    std::fprintf(out,
                 "usage: obbsat accuracy [--pairs N] [--seed S] [--threads T] [--reps K]\n"
                 "                       [--json FILE] [--svg FILE] [--precision float|double]\n"
                 "\n"
                 "Builds N pairs of every hard-case family (see 'obbsat gen --help'), labels\n"
                 "each pair separated, touching or overlapping with the exact oracle, and runs\n"
                 "every method on them on the fastest backend this CPU has; likewise N pairs of\n"
                 "every pose family for the methods on poses (local, conservative and exact on\n"
                 "pose records, shown as e.g. 'local (poses)'), labelled by the exact pose\n"
                 "oracle. Prints per method and family the false positives (collide said, truth\n"
                 "separated), the false negatives split by the truth's class (touching,\n"
                 "overlapping), the error rate, the speed of that scoring run (T threads) and,\n"
                 "for method exact, the share of pairs settled on its exact slow path;\n"
                 "then per method the totals and its speed in Mpairs/s on a typical\n"
                 "broadphase scene (131072 rects, 262144 pairs sorted by first rect, packed\n"
                 "records; for the methods on poses the same rects as pose records; 1 thread,\n"
                 "median of K runs).\n"
                 "\n"
                 "With --precision double: N pairs of every double family (see 'obbsat gen\n"
                 "--help'), labelled by the exact double oracle; rows exact, conservative and\n"
                 "local on double poses, exact and conservative on double corners, and for\n"
                 "contrast float32 exact on the same pairs rounded to\n"
                 "float32, scored against the double truth (pairs float32 cannot hold are\n"
                 "counted apart). Speed is that of the scoring runs (--reps is not used);\n"
                 "--json and --svg write the same rows.\n"
                 "\n"
                 "options:\n");
    print_options(out, accuracy_option_specs());
    std::fprintf(out,
                 "\n"
                 "example:\n"
                 "  obbsat accuracy --pairs 100000 --threads 2 --json acc.json --svg acc.svg\n"
                 "  obbsat accuracy --precision double --pairs 100000\n");
}

int run_accuracy(const arguments& args) {
    const parsed_options options = parse_options(args, accuracy_option_specs());
    accuracy::accuracy_settings settings;
    if (const auto v = options.value("pairs")) {
        settings.pairs_per_family =
            static_cast<std::size_t>(parse_number_option("pairs", *v, 1, 10000000));
    }
    if (const auto v = options.value("seed")) {
        settings.seed = parse_number_option("seed", *v, 0, UINT64_MAX);
    }
    if (const auto v = options.value("threads")) {
        settings.threads = static_cast<unsigned>(parse_number_option("threads", *v, 0, 1024));
    }
    if (const auto v = options.value("reps")) {
        settings.timing_reps = static_cast<unsigned>(parse_number_option("reps", *v, 1, 1000));
    }
    // Created before the long run, so an unwritable path fails at once.
    const std::unique_ptr<io::atomic_output> json = output_for(options, "json");
    const std::unique_ptr<io::atomic_output> svg = output_for(options, "svg");

    if (precision_option(options) == precision::double_) {
        return run_double_accuracy(settings, json.get(), svg.get());
    }

    const std::size_t family_count = suites::all_families().size();
    const std::size_t pose_family_count = suites::all_pose_families().size();
    std::printf("obbsat %s accuracy: %zu pairs per family, %zu families and %zu pose families, "
                "seed %" PRIu64 ", %u scoring thread(s)\n",
                OBBSAT_VERSION, settings.pairs_per_family, family_count, pose_family_count,
                settings.seed, settings.threads);
    std::printf("FP: said collide, truth separated; FN touch / FN overlap: said separated, truth "
                "touching / overlapping\n");
    std::fflush(stdout);

    const bool show_progress = ::isatty(STDERR_FILENO) == 1;
    const accuracy::accuracy_report report = accuracy::measure_accuracy(
        settings, [show_progress](std::size_t done, std::size_t total) {
            if (show_progress) {
                std::fprintf(stderr, "\rscored %zu of %zu families", done, total);
                if (done == total) {
                    std::fprintf(stderr, "; timing every method...\n");
                }
            }
        });
    std::printf("verdicts on the %s backend (the fastest this CPU runs); cpu: %s\n\n",
                backend_name(report.used), report.cpu.c_str());
    accuracy::print_truth_table(stdout, report);
    accuracy::print_method_tables(stdout, report);
    accuracy::print_summary(stdout, report);

    if (json) {
        write_whole(*json, accuracy::accuracy_json(report, OBBSAT_VERSION));
    }
    if (svg) {
        write_whole(*svg, accuracy::accuracy_svg(report));
    }
    return exit_success;
}

}  // namespace obbsat::cli
