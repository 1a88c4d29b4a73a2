// `obbsat demo` run as a user runs it (tools/demo): its usage errors, the rows
// its table times and in which order, the comparisons under the table, and
// the scene query section that --scene-boxes sizes. The cli.demo_* tests of
// CMakeLists.txt run it on larger scenes.
#include "program_runner.hpp"

#include <obbsat/backend.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace {

using obbsat::backend;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;

// ---------------------------------------------------------------------------
// Usage errors.

TEST(demo, usage_errors_exit_2) {
    const scratch s;
    for (const char* args : {"demo --density thick", "demo --reps 0", "demo --rects 1",
                             "demo --pairs 0", "demo --seed -3", "demo --turbo",
                             "demo --method sat5"}) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err.rfind("obbsat: demo: ", 0), 0u) << r.err;
    }
}

// ---------------------------------------------------------------------------
// The demo's table: which rows it times, in which order.

struct demo_row {
    std::string method;
    std::string backend;
    std::string store;
    unsigned threads;
};

// The rows of the demo's table, from the line after its header to the first blank line.
std::vector<demo_row> demo_rows(const std::string& out) {
    const std::vector<std::string> lines = obbsat::cli_test::lines_of(out);
    std::vector<demo_row> rows;
    bool in_table = false;
    for (const std::string& line : lines) {
        if (line.rfind("method ", 0) == 0 && line.find("backend") != std::string::npos) {
            in_table = true;
            continue;
        }
        if (!in_table) {
            continue;
        }
        if (line.empty()) {
            break;
        }
        std::istringstream fields(line);
        demo_row row{};
        fields >> row.method >> row.backend >> row.store >> row.threads;
        rows.push_back(row);
    }
    return rows;
}

// The backends this CPU runs, scalar first then narrowest to widest, as the demo lists them.
std::vector<std::string> runnable_backend_names() {
    std::vector<std::string> names{"scalar"};
    const std::vector<backend> compiled = obbsat::compiled_backends();
    for (auto b = compiled.rbegin(); b != compiled.rend(); ++b) {
        if (*b != backend::scalar && obbsat::cpu_supports(*b)) {
            names.push_back(obbsat::backend_name(*b));
        }
    }
    return names;
}

// The rows the demo should time for `m` on each of `stores`, in its order.
std::vector<demo_row> expected_demo_rows(const std::string& m, const std::vector<std::string>& stores) {
    std::vector<demo_row> rows;
    for (const std::string& store : stores) {
        for (const std::string& b : runnable_backend_names()) {
            for (const unsigned threads : {1u, 2u}) {
                rows.push_back(demo_row{m, b, store, threads});
            }
        }
    }
    return rows;
}

void expect_rows(const std::vector<demo_row>& got, const std::vector<demo_row>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE("row " + std::to_string(i));
        EXPECT_EQ(got[i].method, want[i].method);
        EXPECT_EQ(got[i].backend, want[i].backend);
        EXPECT_EQ(got[i].store, want[i].store);
        EXPECT_EQ(got[i].threads, want[i].threads);
    }
}

std::vector<demo_row> concatenated(std::vector<std::vector<demo_row>> parts) {
    std::vector<demo_row> all;
    for (const auto& part : parts) {
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

TEST(demo, times_local_on_poses_beside_sat4_and_the_conversion_of_poses) {
    const scratch s;
    const run_result r = s.run("demo --rects 2000 --pairs 10000 --reps 1");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<demo_row> rows = demo_rows(r.out);
    expect_rows(rows, concatenated({expected_demo_rows("sat4", {"soa", "records"}),
                                    expected_demo_rows("local", {"poses"})}));
    EXPECT_NE(r.out.find("all " + std::to_string(rows.size()) + " rows agree with the scalar reference"),
              std::string::npos)
        << r.out;
    const std::string best = obbsat::backend_name(obbsat::best_supported_backend());
    EXPECT_NE(r.out.find("poses against corners (" + best + ", 1 thread, the same pairs):\n  local on poses: "),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("x sat4 on records ("), std::string::npos) << r.out;
    // One conversion row per backend, against corners built from angles.
    EXPECT_NE(r.out.find("  angle             rect_records::from_poses"), std::string::npos) << r.out;
    for (const std::string& b : runnable_backend_names()) {
        EXPECT_NE(r.out.find("  rotation vector   convert_to_corners        " + b + " "), std::string::npos)
            << b << "\n" << r.out;
    }
    EXPECT_NE(r.out.find("every convert_to_corners run gave the corners of ref::corners_of"), std::string::npos)
        << r.out;
}

TEST(demo, method_all_times_every_method_on_every_store_it_runs_on) {
    const scratch s;
    const run_result r = s.run("demo --rects 2000 --pairs 10000 --reps 1 --method all");
    ASSERT_EQ(r.status, 0) << r.err;
    // Each method on poses right after the corner test it stands in for.
    expect_rows(demo_rows(r.out), concatenated({
                                      expected_demo_rows("sat4", {"soa", "records"}),
                                      expected_demo_rows("local", {"poses"}),
                                      expected_demo_rows("sat4_centered", {"soa", "records"}),
                                      expected_demo_rows("sat4_double", {"soa", "records"}),
                                      expected_demo_rows("conservative", {"soa", "records", "poses"}),
                                      expected_demo_rows("exact", {"soa", "records", "poses"}),
                                  }));
    for (const char* line : {"  local on poses: ", "  conservative on poses: ", "  exact on poses: "}) {
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    }
    EXPECT_NE(r.out.find("x conservative on records ("), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("x exact on records ("), std::string::npos) << r.out;
}

TEST(demo, method_names_one_method_on_the_stores_it_runs_on) {
    const scratch s;
    const run_result local = s.run("demo --rects 2000 --pairs 10000 --reps 1 --method local");
    ASSERT_EQ(local.status, 0) << local.err;
    expect_rows(demo_rows(local.out), expected_demo_rows("local", {"poses"}));
    EXPECT_EQ(local.out.find("poses against corners"), std::string::npos) << local.out;
    const run_result sat4 = s.run("demo --rects 2000 --pairs 10000 --reps 1 --method sat4");
    ASSERT_EQ(sat4.status, 0) << sat4.err;
    expect_rows(demo_rows(sat4.out), expected_demo_rows("sat4", {"soa", "records"}));
}

// ---------------------------------------------------------------------------
// The scene query section: --scene-boxes N, from 0 to 4294967295, 0 leaving
// it out; a scene of one box has no pairs, but its section still runs.

run_result demo_with_scene_boxes(const scratch& s, const std::string& boxes) {
    return s.run("demo --rects 2000 --pairs 10000 --reps 1 --method sat4 --scene-boxes " + boxes);
}

const std::string scene_section = "\nscene query: ";
const std::string scene_rows_agree = "every row gave the same pairs as the cold query at 1 thread";

TEST(demo, scene_boxes_0_leaves_the_scene_query_out) {
    const scratch s;
    const run_result r = demo_with_scene_boxes(s, "0");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("rows agree with the scalar reference"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(scene_section), std::string::npos) << r.out;
}

TEST(demo, scene_boxes_1_runs_the_scene_query_on_one_box_and_says_it_has_no_pairs) {
    const scratch s;
    const run_result r = demo_with_scene_boxes(s, "1");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(scene_section + "1 poses to every colliding pair"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("a scene of one box has no pairs"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(scene_rows_agree), std::string::npos) << r.out;
    // Every row of the section (uniform and mixed, 1 and 2 threads, cold and
    // frame) found no pairs: 0.00 pairs per box.
    std::size_t rows = 0;
    for (const std::string& line : obbsat::cli_test::lines_of(r.out)) {
        std::istringstream fields(line);
        std::string sizes, query;
        unsigned threads = 0;
        if (fields >> sizes >> threads >> query && (sizes == "uniform" || sizes == "mixed")) {
            ++rows;
            EXPECT_NE(line.find("     0.00  "), std::string::npos) << line;
        }
    }
    EXPECT_EQ(rows, 8u) << r.out;
}

TEST(demo, scene_boxes_2_runs_the_scene_query) {
    const scratch s;
    const run_result r = demo_with_scene_boxes(s, "2");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(scene_section + "2 poses to every colliding pair"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(scene_rows_agree), std::string::npos) << r.out;
}

TEST(demo, scene_boxes_outside_its_range_is_a_usage_error_naming_the_range) {
    const scratch s;
    for (const char* boxes : {"-1", "4294967296", "many"}) {
        const run_result r = demo_with_scene_boxes(s, boxes);
        EXPECT_EQ(r.status, 2) << boxes;
        EXPECT_EQ(r.err, "obbsat: demo: --scene-boxes: expected a whole number from 0 to 4294967295, got '" +
                             std::string(boxes) + "' (see 'obbsat demo --help')\n")
            << boxes;
        EXPECT_EQ(r.out, "") << boxes;
    }
}

TEST(demo, help_states_the_scene_boxes_range) {
    const scratch s;
    const run_result r = s.run("demo --help");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("[--scene-boxes N]"), std::string::npos) << r.out;
    std::string option_line;
    for (const std::string& line : obbsat::cli_test::lines_of(r.out)) {
        if (line.find("  --scene-boxes N  ") == 0) {
            option_line = line;
        }
    }
    EXPECT_NE(option_line.find("0 to 4294967295"), std::string::npos) << r.out;
    EXPECT_NE(option_line.find("0 leaves it out"), std::string::npos) << r.out;
}

}  // namespace
