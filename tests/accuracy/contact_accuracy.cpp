// Not a test: `contact_accuracy [PAIRS] [SEED]` measures the float32 contact
// reference against the exact contact (contact_exact.hpp) on PAIRS pairs
// (default 100000) of every family, as poses and as corners, and prints the
// tables of docs/accuracy.md's "Contacts" section (units: contact_error.hpp).
#include "contact_error.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using obbsat::accuracy::family_errors;

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

}  // namespace

int main(int argc, char** argv) {
    const std::size_t pairs = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    std::string choice_rows, boundary_rows;
    std::size_t mismatched = 0;
    std::printf("| family | form | pairs | skipped | reference face differs | incident face differs | count differs | "
                "normal (u rad) | depth / size | depth (u·R) | point / size | point (u·(O+R)) | separation (u·R) |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    obbsat::accuracy::family_result results[std::size(obbsat::accuracy::all_contact_families)];
    int f = 0;
    for (const obbsat::accuracy::contact_family family : obbsat::accuracy::all_contact_families) {
        const char* name = obbsat::accuracy::contact_family_name(family);
        results[f] = obbsat::accuracy::measure_family(obbsat::accuracy::make_contact_pairs(family, pairs, seed));
        print_row(name, "poses", results[f].poses);
        print_row(name, "corners", results[f].corners);
        std::fflush(stdout);
        mismatched += results[f].poses.mismatched_normals + results[f].corners.mismatched_normals;
        ++f;
    }
    std::printf("\nWhere the exact steps choose another reference face: the float result against the exact "
                "result of the exact choice.\n\n");
    std::printf("| family | form | reference face differs | normal (rad) | depth / size | count differs |\n");
    std::printf("| --- | --- | --- | --- | --- | --- |\n");
    f = 0;
    for (const obbsat::accuracy::contact_family family : obbsat::accuracy::all_contact_families) {
        const char* name = obbsat::accuracy::contact_family_name(family);
        print_choice_row(name, "poses", results[f].poses);
        print_choice_row(name, "corners", results[f].corners);
        ++f;
    }
    std::printf("\nCount differences (same choice): the largest distance from a decision boundary (u·R).\n\n");
    std::printf("| family | form | count differs | boundary (u·R) |\n| --- | --- | --- | --- |\n");
    f = 0;
    for (const obbsat::accuracy::contact_family family : obbsat::accuracy::all_contact_families) {
        const char* name = obbsat::accuracy::contact_family_name(family);
        for (const auto& [form, e] : {std::pair<const char*, const family_errors&>{"poses", results[f].poses},
                                      std::pair<const char*, const family_errors&>{"corners", results[f].corners}}) {
            if (e.count_differs > 0) {
                std::printf("| %s | %s | %zu | %.2f |\n", name, form, e.count_differs, e.count_boundary_u_reach);
            }
        }
        ++f;
    }
    std::printf("\n%zu pairs per family, seed %llu; normals not those of the float choice: %zu\n", pairs,
                static_cast<unsigned long long>(seed), mismatched);
    return mismatched == 0 ? 0 : 1;
}
