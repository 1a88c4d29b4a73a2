#include "accuracy/accuracy_json.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace obbsat::accuracy {

namespace {

// A JSON string: quotes and backslashes escaped, control characters as \u00XX.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
            out += escape;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number(std::uint64_t value) { return std::to_string(value); }

// Round-trips every double; JSON has no infinity or NaN, so those become null.
std::string number(double value) {
    if (!std::isfinite(value)) {
        return "null";
    }
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string counts_fields(const error_counts& c) {
    return "\"pairs\": " + number(c.pairs) + ", \"false_positives\": " + number(c.false_positives) +
           ", \"false_negatives\": " + number(c.false_negatives()) +
           ", \"false_negatives_touching\": " + number(c.missed_touching) +
           ", \"false_negatives_overlapping\": " + number(c.missed_overlapping) +
           ", \"errors\": " + number(c.errors()) + ", \"error_rate\": " + number(c.error_rate()) +
           ", \"slow_path_pairs\": " + number(c.slow_path_pairs);
}

std::string families_array(const std::vector<family_truth>& families) {
    std::string out = "[\n";
    for (std::size_t f = 0; f < families.size(); ++f) {
        const family_truth& t = families[f];
        out += "    {\"name\": " + quoted(t.name) + ", \"pairs\": " + number(t.pairs) +
               ", \"separated\": " + number(t.separated) + ", \"touching\": " + number(t.touching) +
               ", \"overlapping\": " + number(t.overlapping) + "}";
        out += f + 1 < families.size() ? ",\n" : "\n";
    }
    return out + "  ]";
}

}  // namespace

std::string accuracy_json(const accuracy_report& report, const std::string& version) {
    const accuracy_settings& s = report.settings;
    const throughput_scene& scene = report.timing_scene;
    std::string out = "{\n";
    out += "  \"format\": \"obbsat-accuracy-2\",\n";
    out += "  \"version\": " + quoted(version) + ",\n";
    out += "  \"seed\": " + number(s.seed) + ",\n";
    out += "  \"pairs_per_family\": " + number(static_cast<std::uint64_t>(s.pairs_per_family)) + ",\n";
    out += "  \"threads\": " + number(std::uint64_t{s.threads}) + ",\n";
    out += "  \"backend\": " + quoted(backend_name(report.used)) + ",\n";
    out += "  \"cpu\": " + quoted(report.cpu) + ",\n";
    out += "  \"throughput_scene\": {\"density\": " + quoted(scene.density) +
           ", \"rects\": " + number(static_cast<std::uint64_t>(scene.rects)) +
           ", \"pairs\": " + number(static_cast<std::uint64_t>(scene.pairs)) +
           ", \"store\": " + quoted(scene.store) + ", \"pose_store\": " + quoted(scene.pose_store) +
           ", \"order\": " + quoted(scene.order) +
           ", \"threads\": " + number(std::uint64_t{scene.threads}) +
           ", \"timed_runs\": " + number(std::uint64_t{s.measure_speed ? s.timing_reps : 0u}) + "},\n";

    out += "  \"families\": " + families_array(report.families) + ",\n";
    out += "  \"pose_families\": " + families_array(report.pose_families) + ",\n";

    out += "  \"methods\": [\n";
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
        const method_result& r = report.methods[m];
        out += "    {\n      \"name\": " + quoted(method_name(r.test)) + ",\n";
        out += "      \"store\": " + quoted(store_name(r.store)) + ",\n";
        out += "      \"label\": " + quoted(r.label()) + ",\n";
        out += "      \"mpairs_per_second\": " +
               (s.measure_speed ? number(r.mpairs_per_second) : std::string("null")) + ",\n";
        out += "      \"total\": {" + counts_fields(r.total) + "},\n";
        out += "      \"families\": [\n";
        const std::vector<family_truth>& families = families_of(report, r.store);
        for (std::size_t f = 0; f < r.per_family.size(); ++f) {
            out += "        {\"family\": " + quoted(families[f].name) + ", " +
                   counts_fields(r.per_family[f]) +
                   ", \"mpairs_per_second\": " + number(r.family_mpairs_per_second[f]) + "}";
            out += f + 1 < r.per_family.size() ? ",\n" : "\n";
        }
        out += "      ]\n    }";
        out += m + 1 < report.methods.size() ? ",\n" : "\n";
    }
    out += "  ]\n}\n";
    return out;
}

}  // namespace obbsat::accuracy
