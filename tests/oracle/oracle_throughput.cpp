// Times the exact oracle on every suite family and prints, per family, the
// contact classes, the share of pairs within a few float steps of a class
// boundary, the quad forms seen, and pairs per second.
//
// usage: oracle_throughput [pairs per family = 10000] [seed = 1] [threads = 1]
#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/oracle/quad_region.hpp>
#include <obbsat/suites/boundary.hpp>
#include <obbsat/suites/suite.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace {

unsigned long parse_count(const char* text, const char* what) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text, &end, 10);
    if (*text == '\0' || *end != '\0') {
        std::fprintf(stderr, "oracle_throughput: %s must be a non-negative integer, got '%s'\n", what, text);
        std::exit(2);
    }
    return value;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t pairs = argc > 1 ? parse_count(argv[1], "pairs") : 10000;
    const std::uint64_t seed = argc > 2 ? parse_count(argv[2], "seed") : 1;
    const auto threads = static_cast<unsigned>(argc > 3 ? parse_count(argv[3], "threads") : 1);
    std::printf("%-17s %9s %9s %9s %9s %8s  %12s  %s\n", "family", "pairs", "S", "T", "O",
                "near4", "pairs/s", "quad forms");
    double total_seconds = 0.0;
    std::size_t total_pairs = 0;
    for (const obbsat::suites::family f : obbsat::suites::all_families()) {
        const obbsat::suites::suite s = obbsat::suites::make_family(f, seed, pairs);
        std::vector<obbsat::oracle::contact> out(s.pairs.size());
        const auto start = std::chrono::steady_clock::now();
        obbsat::oracle::classify_pairs(s.rects.data(), s.rects.size(), s.pairs.data(), s.pairs.size(),
                                       out.data(), threads);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        total_seconds += seconds;
        total_pairs += s.pairs.size();
        std::size_t count[3] = {0, 0, 0};
        for (const obbsat::oracle::contact c : out) {
            ++count[static_cast<int>(c)];
        }
        // The boundary share costs up to 17 oracle calls a pair: sample it, with
        // an odd stride so that families built in cycles are sampled evenly.
        const std::size_t stride = (s.pairs.size() / 50000) | 1u;
        std::size_t near = 0, sampled = 0;
        for (std::size_t i = 0; i < s.pairs.size(); i += stride, ++sampled) {
            near += obbsat::suites::near_contact_boundary(s.rects[s.pairs[i].a], s.rects[s.pairs[i].b], 4);
        }
        std::map<std::string, std::size_t> forms;
        for (const obbsat::rect& r : s.rects) {
            ++forms[obbsat::oracle::quad_form_name(obbsat::oracle::region_of(r).form)];
        }
        std::string form_text;
        for (const auto& [name, n] : forms) {
            form_text += name + "=" + std::to_string(n) + " ";
        }
        std::printf("%-17s %9zu %9zu %9zu %9zu %7.1f%%  %12.0f  %s\n", obbsat::suites::family_name(f),
                    s.pairs.size(), count[0], count[1], count[2],
                    sampled == 0 ? 0.0 : 100.0 * static_cast<double>(near) / static_cast<double>(sampled),
                    static_cast<double>(s.pairs.size()) / seconds, form_text.c_str());
    }
    std::printf("all families: %zu pairs in %.3f s: %.0f pairs/s with %u thread(s)\n", total_pairs,
                total_seconds, static_cast<double>(total_pairs) / total_seconds, threads);
    return 0;
}
