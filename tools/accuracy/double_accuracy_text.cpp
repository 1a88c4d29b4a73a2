#include "accuracy/double_accuracy_text.hpp"

#include "accuracy/accuracy_text.hpp"

#include <cinttypes>

namespace obbsat::accuracy {

namespace {

void print_truths(std::FILE* out, const char* title, const char* all_name,
                  const std::vector<family_truth>& families) {
    std::fprintf(out, "%s\n", title);
    std::fprintf(out, "  %-22s %9s %10s %9s %12s\n", "family", "pairs", "separated", "touching", "overlapping");
    family_truth all;
    for (const family_truth& f : families) {
        std::fprintf(out, "  %-22s %9" PRIu64 " %10" PRIu64 " %9" PRIu64 " %12" PRIu64 "\n", f.name.c_str(),
                     f.pairs, f.separated, f.touching, f.overlapping);
        all.pairs += f.pairs;
        all.separated += f.separated;
        all.touching += f.touching;
        all.overlapping += f.overlapping;
    }
    std::fprintf(out, "  %-22s %9" PRIu64 " %10" PRIu64 " %9" PRIu64 " %12" PRIu64 "\n\n", all_name, all.pairs,
                 all.separated, all.touching, all.overlapping);
}

const char* all_name(store_kind s) { return s == store_kind::poses ? "all pose families" : "all corner families"; }

// `speed` < 0: no speed (the all-families row).
void print_row(std::FILE* out, const char* name, const error_counts& c, double speed, bool slow_path,
               bool float32, std::uint64_t not_representable) {
    std::fprintf(out, "  %-22s %9" PRIu64 " %8" PRIu64 " %9" PRIu64 " %11" PRIu64 "  %10s", name, c.pairs,
                 c.false_positives, c.missed_touching, c.missed_overlapping, format_rate(c.error_rate()).c_str());
    if (speed >= 0.0) {
        std::fprintf(out, "  %8.1f", speed);
    } else {
        std::fprintf(out, "  %8s", "");
    }
    if (slow_path) {
        const double share = c.pairs == 0 ? 0.0 : 100.0 * static_cast<double>(c.slow_path_pairs) /
                                                      static_cast<double>(c.pairs);
        std::fprintf(out, "  %8.3f%%", share);
    }
    if (float32) {
        std::fprintf(out, "  %12" PRIu64, not_representable);
    }
    std::fprintf(out, "\n");
}

}  // namespace

void print_double_report(std::FILE* out, const double_accuracy_report& report) {
    print_truths(out, "truth of the double pose families (exact double pose oracle), pairs per contact class:",
                 all_name(store_kind::poses), report.pose_families);
    print_truths(out, "truth of the double corner families (exact double oracle), pairs per contact class:",
                 all_name(store_kind::corners), report.corner_families);
    std::fprintf(out,
                 "Mpairs/s per family: the one scoring run over the family's pairs, %u thread(s); float32 rows:\n"
                 "exact on the same pairs rounded to float32, scored against the double truth; 'not in float'\n"
                 "counts the pairs float32 cannot hold (left out of that row's counts)\n\n",
                 report.settings.threads);
    for (const double_method_result& m : report.methods) {
        const bool slow_path = m.test == method::exact;
        std::fprintf(out, "method %s:\n", m.label().c_str());
        std::fprintf(out, "  %-22s %9s %8s %9s %11s  %10s  %8s", "family", "pairs", "FP", "FN touch", "FN overlap",
                     "error rate", "Mpairs/s");
        if (slow_path) {
            std::fprintf(out, "  %9s", "slow path");
        }
        if (m.float32) {
            std::fprintf(out, "  %12s", "not in float");
        }
        std::fprintf(out, "\n");
        const std::vector<family_truth>& families = families_of(report, m.store);
        for (std::size_t f = 0; f < families.size(); ++f) {
            print_row(out, families[f].name.c_str(), m.per_family[f], m.family_mpairs_per_second[f], slow_path,
                      m.float32, m.not_representable[f]);
        }
        print_row(out, all_name(m.store), m.total, -1.0, slow_path, m.float32, m.total_not_representable);
        std::fprintf(out, "\n");
    }
    std::fprintf(out,
                 "summary over all families of each row's store; Mpairs/s over all its scoring runs\n"
                 "(boundary-heavy pairs, %u thread(s), %s backend):\n",
                 report.settings.threads, backend_name(report.used));
    std::fprintf(out, "  %-30s %9s %9s %9s %11s  %10s  %9s  %12s\n", "method", "pairs", "FP", "FN touch",
                 "FN overlap", "error rate", "Mpairs/s", "not in float");
    for (const double_method_result& m : report.methods) {
        const error_counts& c = m.total;
        std::fprintf(out, "  %-30s %9" PRIu64 " %9" PRIu64 " %9" PRIu64 " %11" PRIu64 "  %10s  %9.1f  %12s\n",
                     m.label().c_str(), c.pairs, c.false_positives, c.missed_touching, c.missed_overlapping,
                     format_rate(c.error_rate()).c_str(), m.mpairs_per_second,
                     m.float32 ? std::to_string(m.total_not_representable).c_str() : "-");
    }
}

}  // namespace obbsat::accuracy
