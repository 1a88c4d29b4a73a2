#include "accuracy/accuracy_text.hpp"

#include <cinttypes>

namespace obbsat::accuracy {

std::string format_rate(double rate) {
    if (rate == 0.0) {
        return "0";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", rate);
    return text;
}

namespace {

double percent(std::uint64_t part, std::uint64_t whole) {
    return whole == 0 ? 0.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

// `speed` < 0: no speed column (the all-families row).
void print_counts_row(std::FILE* out, const char* name, const error_counts& c, double speed,
                      bool slow_path) {
    std::fprintf(out, "  %-17s %9" PRIu64 " %8" PRIu64 " %9" PRIu64 " %11" PRIu64 "  %10s", name,
                 c.pairs, c.false_positives, c.missed_touching, c.missed_overlapping,
                 format_rate(c.error_rate()).c_str());
    if (speed >= 0.0) {
        std::fprintf(out, "  %8.1f", speed);
    } else {
        std::fprintf(out, "  %8s", "");
    }
    if (slow_path) {
        std::fprintf(out, "  %8.3f%%", percent(c.slow_path_pairs, c.pairs));
    }
    std::fprintf(out, "\n");
}

void print_truths(std::FILE* out, const char* title, const char* all_name,
                  const std::vector<family_truth>& families) {
    std::fprintf(out, "%s\n", title);
    std::fprintf(out, "  %-17s %9s %10s %9s %12s\n", "family", "pairs", "separated", "touching",
                 "overlapping");
    family_truth all;
    for (const family_truth& f : families) {
        std::fprintf(out, "  %-17s %9" PRIu64 " %10" PRIu64 " %9" PRIu64 " %12" PRIu64 "\n",
                     f.name.c_str(), f.pairs, f.separated, f.touching, f.overlapping);
        all.pairs += f.pairs;
        all.separated += f.separated;
        all.touching += f.touching;
        all.overlapping += f.overlapping;
    }
    std::fprintf(out, "  %-17s %9" PRIu64 " %10" PRIu64 " %9" PRIu64 " %12" PRIu64 "\n\n",
                 all_name, all.pairs, all.separated, all.touching, all.overlapping);
}

// The name of the row of totals over the families of store `s`.
const char* all_families_name(store_kind s) {
    return s == store_kind::poses ? "all pose families" : "all families";
}

}  // namespace

void print_truth_table(std::FILE* out, const accuracy_report& report) {
    print_truths(out, "truth (exact oracle), pairs per contact class:", all_families_name(store_kind::corners),
                 report.families);
    if (!report.pose_families.empty()) {
        print_truths(out, "truth of the pose families (exact pose oracle), pairs per contact class:",
                     all_families_name(store_kind::poses), report.pose_families);
    }
}

void print_method_tables(std::FILE* out, const accuracy_report& report) {
    std::fprintf(out, "Mpairs/s per family: the one scoring run over the family's pairs, %u thread(s);\n"
                      "boundary pairs cost method exact its slow path\n\n",
                 report.settings.threads);
    for (const method_result& m : report.methods) {
        const bool slow_path = m.test == method::exact;
        if (m.store == store_kind::poses) {
            std::fprintf(out, "method %s, on the pose families:\n", m.label().c_str());
        } else {
            std::fprintf(out, "method %s:\n", m.label().c_str());
        }
        std::fprintf(out, "  %-17s %9s %8s %9s %11s  %10s  %8s", "family", "pairs", "FP", "FN touch",
                     "FN overlap", "error rate", "Mpairs/s");
        if (slow_path) {
            std::fprintf(out, "  %9s", "slow path");
        }
        std::fprintf(out, "\n");
        const std::vector<family_truth>& families = families_of(report, m.store);
        for (std::size_t f = 0; f < families.size(); ++f) {
            print_counts_row(out, families[f].name.c_str(), m.per_family[f],
                             m.family_mpairs_per_second[f], slow_path);
        }
        print_counts_row(out, all_families_name(m.store), m.total, -1.0, slow_path);
        std::fprintf(out, "\n");
    }
}

void print_summary(std::FILE* out, const accuracy_report& report) {
    const throughput_scene& scene = report.timing_scene;
    std::fprintf(out, "summary over all families (methods on poses: over all pose families)");
    if (report.settings.measure_speed) {
        std::fprintf(out,
                     "; Mpairs/s on a %s\nbroadphase scene (%zu rects, %zu candidate pairs, %s,\n"
                     "%s; methods on poses: the same rects as %s; %u thread, %s backend,\n"
                     "median of %u runs)",
                     scene.density, scene.rects, scene.pairs, scene.order, scene.store,
                     scene.pose_store, scene.threads, backend_name(report.used),
                     report.settings.timing_reps);
    }
    std::fprintf(out, ":\n");
    std::fprintf(out, "  %-20s %9s %9s %9s %11s  %10s  %9s\n", "method", "pairs", "FP", "FN touch",
                 "FN overlap", "error rate", "Mpairs/s");
    for (const method_result& m : report.methods) {
        const error_counts& c = m.total;
        std::fprintf(out, "  %-20s %9" PRIu64 " %9" PRIu64 " %9" PRIu64 " %11" PRIu64 "  %10s",
                     m.label().c_str(), c.pairs, c.false_positives, c.missed_touching,
                     c.missed_overlapping, format_rate(c.error_rate()).c_str());
        if (report.settings.measure_speed) {
            std::fprintf(out, "  %9.1f\n", m.mpairs_per_second);
        } else {
            std::fprintf(out, "  %9s\n", "-");
        }
    }
}

}  // namespace obbsat::accuracy
