#include "accuracy/accuracy_brief.hpp"

#include "accuracy/accuracy_report.hpp"
#include "accuracy/accuracy_text.hpp"

#include <cinttypes>

namespace obbsat::accuracy {

namespace {

// Few runs: the brief is a sketch beside the demo's own timings, not a benchmark.
constexpr unsigned brief_timing_reps = 5;

const timed_method* find_timed(const std::vector<timed_method>& timed, const method_result& m) {
    for (const timed_method& t : timed) {
        if (t.test == m.test && t.store == m.store) {
            return &t;
        }
    }
    return nullptr;
}

}  // namespace

void print_accuracy_brief(std::FILE* out, const std::vector<timed_method>& timed,
                          std::size_t pairs_per_family) {
    accuracy_settings settings;
    settings.pairs_per_family = pairs_per_family;
    settings.measure_speed = false;
    const accuracy_report report = measure_accuracy(settings);

    // Every method is timed on one scene, so the column compares like with
    // like; the caller's own figures, from its own scene, stand beside it.
    std::vector<method_on_store> methods;
    for (const method_result& m : report.methods) {
        methods.push_back({m.test, m.store});
    }
    const std::vector<double> speeds =
        measure_throughput(methods, report.used, brief_timing_reps, report.timing_scene);

    std::fprintf(out,
                 "\naccuracy against the exact oracle: %zu pairs of each of %zu hard-case families "
                 "(methods on poses: of each of %zu pose families; seed %" PRIu64 "); the full "
                 "table: obbsat accuracy\n"
                 "speed: Mpairs/s on the accuracy scene (%s, %zu pairs over %zu rects, records or "
                 "pose records, 1 thread, %s, median of %u runs)\nand, where this demo timed the "
                 "method, on this demo's scene (records, 1 thread, %s)\n",
                 pairs_per_family, report.families.size(), report.pose_families.size(),
                 settings.seed, report.timing_scene.density, report.timing_scene.pairs,
                 report.timing_scene.rects, backend_name(report.used), brief_timing_reps,
                 backend_name(report.used));
    std::fprintf(out, "  %-20s %10s %9s %9s %11s\n", "method", "error rate", "false neg",
                 "Mpairs/s", "demo scene");
    for (std::size_t i = 0; i < report.methods.size(); ++i) {
        const method_result& m = report.methods[i];
        std::fprintf(out, "  %-20s %10s %9" PRIu64 " %9.1f", m.label().c_str(),
                     format_rate(m.total.error_rate()).c_str(), m.total.false_negatives(), speeds[i]);
        if (const timed_method* t = find_timed(timed, m)) {
            std::fprintf(out, " %11.1f\n", t->mpairs_per_second);
        } else {
            std::fprintf(out, " %11s\n", "-");
        }
    }
}

}  // namespace obbsat::accuracy
