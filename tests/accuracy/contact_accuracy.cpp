// Not a test: `contact_accuracy [PAIRS] [SEED] [float|double]` measures the
// float32 contact reference, and the double contacts of the public entry points,
// against the exact contact (contact_exact.hpp) on PAIRS pairs (default
// 100000) of every family, as poses and as corners, and prints the tables of
// docs/accuracy.md's "Contacts" section (units: contact_error.hpp); with no
// third argument, the float tables and then the double ones.
#include "contact_error.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using obbsat::accuracy::contact_family;
using obbsat::accuracy::family_errors;
using obbsat::accuracy::family_result;

void print_row(const char* family, const char* form, const family_errors& e) {
    std::printf("| %s | %s | %zu | %zu | %zu | %zu | %zu | %.2f | %.2e | %.2f | %.2e | %.2f | %.2f |\n", family, form,
                e.pairs - e.skipped, e.skipped, e.choice_differs, e.incident_differs, e.count_differs, e.normal_u, e.depth_size,
                e.depth_u_reach, e.point_size, e.point_u_scale, e.separation_u_reach);
}

void print_choice_row(const char* family, const char* form, const family_errors& e) {
    if (e.choice_differs == 0) {
        return;
    }
    std::printf("| %s | %s | %zu | %.2e | %.2e | %zu |\n", family, form, e.choice_differs, e.normal_exact_choice,
                e.depth_exact_choice_size, e.count_differs_exact_choice);
}

/// The three tables over `families`, each measured by `measure`; returns how
/// many normals were not those of the rounded reference's choice.
template <std::size_t N, class Measure>
std::size_t print_tables(const char* precision, const contact_family (&families)[N], Measure measure) {
    std::size_t mismatched = 0;
    std::printf("Contacts in %s.\n\n", precision);
    std::printf("| family | form | pairs | skipped | reference face differs | incident face differs | count differs | "
                "normal (u rad) | depth / size | depth (u·R) | point / size | point (u·(O+R)) | separation (u·R) |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    std::vector<family_result> results;
    for (const contact_family family : families) {
        const char* name = obbsat::accuracy::contact_family_name(family);
        results.push_back(measure(family));
        print_row(name, "poses", results.back().poses);
        print_row(name, "corners", results.back().corners);
        std::fflush(stdout);
        mismatched += results.back().poses.mismatched_normals + results.back().corners.mismatched_normals;
    }
    std::printf("\nWhere the exact steps choose another reference face: the %s result against the exact "
                "result of the exact choice.\n\n", precision);
    std::printf("| family | form | reference face differs | normal (rad) | depth / size | count differs |\n");
    std::printf("| --- | --- | --- | --- | --- | --- |\n");
    for (std::size_t f = 0; f < N; ++f) {
        const char* name = obbsat::accuracy::contact_family_name(families[f]);
        print_choice_row(name, "poses", results[f].poses);
        print_choice_row(name, "corners", results[f].corners);
    }
    std::printf("\nCount differences (same choice): the largest distance from a decision boundary (u·R).\n\n");
    std::printf("| family | form | count differs | boundary (u·R) |\n| --- | --- | --- | --- |\n");
    for (std::size_t f = 0; f < N; ++f) {
        const char* name = obbsat::accuracy::contact_family_name(families[f]);
        for (const auto& [form, e] : {std::pair<const char*, const family_errors&>{"poses", results[f].poses},
                                      std::pair<const char*, const family_errors&>{"corners", results[f].corners}}) {
            if (e.count_differs > 0) {
                std::printf("| %s | %s | %zu | %.2f |\n", name, form, e.count_differs, e.count_boundary_u_reach);
            }
        }
    }
    std::printf("\n");
    return mismatched;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t pairs = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    const char* only = argc > 3 ? argv[3] : "";
    if (*only != '\0' && std::strcmp(only, "float") != 0 && std::strcmp(only, "double") != 0) {
        std::fprintf(stderr, "usage: contact_accuracy [PAIRS] [SEED] [float|double]\n");
        return 2;
    }
    std::size_t mismatched = 0;
    if (std::strcmp(only, "double") != 0) {
        mismatched += print_tables("float32 (the reference)", obbsat::accuracy::all_contact_families,
                                   [&](contact_family family) {
                                       return obbsat::accuracy::measure_family(
                                           obbsat::accuracy::make_contact_pairs(family, pairs, seed));
                                   });
    }
    if (std::strcmp(only, "float") != 0) {
        mismatched += print_tables("double (contact_stream on pose_records64 and rect_records64)",
                                   obbsat::accuracy::all_contact_families64, [&](contact_family family) {
                                       return obbsat::accuracy::measure_family(
                                           obbsat::accuracy::make_contact_pairs64(family, pairs, seed));
                                   });
    }
    std::printf("%zu pairs per family, seed %llu; normals not those of the rounded reference's choice: %zu\n", pairs,
                static_cast<unsigned long long>(seed), mismatched);
    return mismatched == 0 ? 0 : 1;
}
