// The built obbsat program, run through the shell as a user runs it: exit
// statuses, exact error messages, --out left untouched on error, and verdict
// files identical for every backend this CPU runs.
#include "io/csv_input.hpp"
#include "program_runner.hpp"
#include "test_support/shared_cases.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using obbsat::backend;
using obbsat::method;
using obbsat::pair_index;
using obbsat::point;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::store_kind;

using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

const std::string unit_rect = "0,1,1,1,1,0,0,0\n";
const std::string unit_pose = "0.5,0.5,0.5,0.5,1,0\n";  // the same unit square

std::string method_list(const std::vector<method>& methods = obbsat::all_methods()) {
    std::string known;
    for (const method m : methods) {
        known += (known.empty() ? "" : ", ") + std::string(obbsat::method_name(m));
    }
    return known;
}

// The scalar reference of each method, from scalar_ref/, called in process.
bool reference_collides(method m, const rect& a, const rect& b) { return obbsat::method_reference(m)(a, b); }

// ---------------------------------------------------------------------------
// Help, version and usage errors.

TEST(program, prints_its_version) {
    const scratch s;
    const run_result r = s.run("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "obbsat " OBBSAT_VERSION "\n");
}

TEST(program, every_command_has_help_with_an_example) {
    const scratch s;
    for (const char* args : {"--help", "collide --help", "pairs --help", "backends --help", "demo --help"}) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 0) << args;
        EXPECT_NE(r.out.find("usage: obbsat"), std::string::npos) << args;
        EXPECT_NE(r.out.find("example:\n  obbsat"), std::string::npos) << args;
        EXPECT_EQ(r.err, "") << args;
    }
}

TEST(program, no_command_or_an_unknown_one_is_a_usage_error) {
    const scratch s;
    const run_result none = s.run("");
    EXPECT_EQ(none.status, 2);
    EXPECT_NE(none.err.find("usage: obbsat"), std::string::npos);
    const run_result bogus = s.run("frobnicate");
    EXPECT_EQ(bogus.status, 2);
    EXPECT_EQ(bogus.err, "obbsat: unknown command 'frobnicate' (see 'obbsat --help')\n");
}

TEST(program, collide_usage_errors_exit_2_with_the_reason) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect);
    write_file(s.file("P.csv"), "0,0\n");
    const std::string files = "--rects R.csv --pairs P.csv ";
    const std::string see = " (see 'obbsat collide --help')\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"collide --rects R.csv", "missing required option --pairs"},
        {"collide --pairs P.csv", "missing required option --rects or --poses"},
        {"collide --rects R.csv --poses R.csv --pairs P.csv",
         "--rects and --poses both given; the rectangles come from one of them"},
        {"collide --poses R.csv", "missing required option --pairs"},
        {"collide --poses - --pairs -", "--poses and --pairs cannot both read standard input ('-')"},
        {"collide " + files + "--bogus 1", "unknown option --bogus"},
        {"collide " + files + "extra", "unexpected argument 'extra'"},
        {"collide " + files + "--rects R.csv", "option --rects given twice"},
        {"collide " + files + "--out", "option --out needs a value (FILE)"},
        {"collide " + files + "--threads x", "--threads: expected a whole number from 0 to 1024, got 'x'"},
        {"collide " + files + "--threads -1", "--threads: expected a whole number from 0 to 1024, got '-1'"},
        {"collide " + files + "--threads=5000",
         "--threads: expected a whole number from 0 to 1024, got '5000'"},
        {"collide " + files + "--backend fast",
         "--backend: unknown backend 'fast' (expected auto, scalar, sse2, avx2 or avx512)"},
        {"collide " + files + "--method sat5", "--method: unknown method 'sat5' (expected " +
                                                   method_list() + ")"},
    };
    for (const auto& [args, reason] : cases) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "obbsat: collide: " + reason + see) << args;
        EXPECT_EQ(r.out, "") << args;
    }
}

TEST(program, collide_help_states_both_files_and_the_methods_on_each) {
    const scratch s;
    const run_result r = s.run("collide --help");
    ASSERT_EQ(r.status, 0);
    const std::vector<std::string> expected = {
        "(--rects FILE | --poses FILE)",
        "--poses FILE",
        "'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle'",
        "default: sat4 on --rects, local on --poses",
        "on --rects: " + method_list(obbsat::methods_on(store_kind::corners)) + "\n",
        "on --poses: " + method_list(obbsat::methods_on(store_kind::poses)) + "\n",
        "angle in radians",
        "obbsat collide --poses"};
    for (const std::string& text : expected) {
        EXPECT_NE(r.out.find(text), std::string::npos) << text << " not in\n" << r.out;
    }
    const run_result main_help = s.run("--help");
    EXPECT_NE(main_help.out.find("--poses"), std::string::npos) << main_help.out;
}

// A method is checked against the store before any file is read: the message
// names the method, the store and the methods that run there.
TEST(program, a_method_that_does_not_run_on_the_store_is_a_usage_error) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect);
    write_file(s.file("Q.csv"), unit_pose);
    write_file(s.file("P.csv"), "0,0\n");
    write_file(s.file("v.txt"), "previous verdicts\n");
    std::size_t refused = 0;
    for (const store_kind store : {store_kind::corners, store_kind::poses}) {
        const std::string option = store == store_kind::corners ? "rects" : "poses";
        const std::string file = store == store_kind::corners ? "R.csv" : "Q.csv";
        for (const method m : obbsat::all_methods()) {
            if (obbsat::runs_on(m, store)) {
                continue;
            }
            const std::string name = obbsat::method_name(m);
            const std::string args = "collide --" + option + " " + file + " --pairs P.csv --method " + name;
            const run_result r = s.run(args + " --out v.txt");
            EXPECT_EQ(r.status, 2) << args;
            const std::string store_text = obbsat::store_name(store);
            EXPECT_EQ(r.err, "obbsat: collide: --method " + name + " does not run on " + store_text + " (--" +
                                 option + "); the methods on " + store_text + " are " +
                                 method_list(obbsat::methods_on(store)) + " (see 'obbsat collide --help')\n")
                << args;
            EXPECT_EQ(r.out, "") << args;
            EXPECT_EQ(read_file(s.file("v.txt")), "previous verdicts\n") << args;
            // Refused before the files are opened.
            EXPECT_EQ(s.run("collide --" + option + " missing.csv --pairs P.csv --method " + name).err,
                      r.err)
                << args;
            ++refused;
        }
    }
    EXPECT_GT(refused, 0u);
}

// ---------------------------------------------------------------------------
// Bad input: exit 2, "obbsat: FILE:LINE: reason", --out untouched.

class bad_input : public ::testing::Test {
protected:
    void SetUp() override {
        write_file(s.file("v.txt"), "previous verdicts\n");
        write_file(s.file("R.csv"), "# ulx,uly,urx,ury,lrx,lry,llx,lly\n" + unit_rect + unit_rect);
        write_file(s.file("P.csv"), "0,1\n1,0\n");
        write_file(s.file("Q.csv"), "# cx,cy,hx,hy,c,s\n" + unit_pose + unit_pose);
    }

    // Runs collide with --out v.txt and checks the common promises.
    void expect_rejected(const std::string& args, const std::string& message,
                         const std::string& env = "") {
        const run_result r = s.run("collide " + args + " --out v.txt", env);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "obbsat: " + message + "\n") << args;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(read_file(s.file("v.txt")), "previous verdicts\n") << args;
        std::vector<std::string> left = s.entries();
        left.erase(std::remove_if(left.begin(), left.end(),
                                  [](const std::string& n) { return n.rfind('.', 0) != 0; }),
                   left.end());
        EXPECT_TRUE(left.empty()) << "temporary output left behind: " << left.front();
    }

    scratch s;
};

TEST_F(bad_input, a_bad_number_names_file_line_and_field) {
    write_file(s.file("bad.csv"), unit_rect + "\n0,abc,1,1,1,0,0,0\n");
    expect_rejected("--rects bad.csv --pairs P.csv",
                    "bad.csv:3: field 2 (uly): 'abc' is not a number");
}

TEST_F(bad_input, an_overflowing_or_non_finite_number_is_rejected) {
    write_file(s.file("big.csv"), unit_rect + "0,1,1e39,1,1,0,0,0\n");
    expect_rejected("--rects big.csv --pairs P.csv",
                    "big.csv:2: field 3 (urx): '1e39' is out of float range (magnitude above "
                    "3.40282347e+38)");
    write_file(s.file("nan.csv"), "0,1,1,1,1,0,0,nan\r\n");
    expect_rejected("--rects nan.csv --pairs P.csv", "nan.csv:1: field 8 (lly): 'nan' is not finite");
}

TEST_F(bad_input, a_wrong_field_count_is_rejected) {
    write_file(s.file("short.csv"), "0,1,1,1,1,0,0\n");
    expect_rejected("--rects short.csv --pairs P.csv",
                    "short.csv:1: expected 8 comma-separated fields "
                    "(ulx,uly,urx,ury,lrx,lry,llx,lly), found 7");
    write_file(s.file("triple.csv"), "0,1\n0,1,1\n");
    expect_rejected("--rects R.csv --pairs triple.csv",
                    "triple.csv:2: expected 2 comma-separated fields (i,j), found 3");
}

TEST_F(bad_input, bad_indices_are_rejected) {
    write_file(s.file("neg.csv"), "0,1\n-1,0\n");
    expect_rejected("--rects R.csv --pairs neg.csv",
                    "neg.csv:2: field 1 (i): '-1' is negative; indices are 0-based and unsigned");
    write_file(s.file("wide.csv"), "0,4294967296\n");
    expect_rejected("--rects R.csv --pairs wide.csv",
                    "wide.csv:1: field 2 (j): '4294967296' is too large for a 32-bit index "
                    "(largest 4294967295)");
    write_file(s.file("far.csv"), "0,1\n\n1,2\n");
    expect_rejected("--rects R.csv --pairs far.csv",
                    "far.csv:3: index 2 is out of range: R.csv holds 2 rectangles (indices 0 to 1)");
}

TEST_F(bad_input, pairs_into_an_empty_rectangle_file_are_rejected) {
    write_file(s.file("none.csv"), "# nothing here\n");
    expect_rejected("--rects none.csv --pairs P.csv",
                    "P.csv:1: index 0 refers to a rectangle, but none.csv holds none");
}

TEST_F(bad_input, a_bad_line_after_the_first_chunk_still_leaves_out_untouched) {
    std::string many;
    many.reserve(5'000'000);
    for (int i = 0; i < 1'200'000; ++i) {
        many += (i % 2 == 0) ? "0,1\n" : "1,0\n";
    }
    many += "1,x\n";
    write_file(s.file("many.csv"), many);
    expect_rejected("--rects R.csv --pairs many.csv",
                    "many.csv:1200001: field 2 (j): 'x' is not an unsigned decimal integer");
}

TEST_F(bad_input, a_bad_line_on_standard_input_is_named_stdin) {
    write_file(s.file("bad_pairs.csv"), "0,1\n1,1,1\n");
    const run_result r = s.run("collide --rects R.csv --pairs - --out v.txt", "",
                               "< '" + s.file("bad_pairs.csv").string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "obbsat: <stdin>:2: expected 2 comma-separated fields (i,j), found 3\n");
    EXPECT_EQ(read_file(s.file("v.txt")), "previous verdicts\n");
}

TEST_F(bad_input, missing_files_and_unwritable_output_are_rejected) {
    expect_rejected("--rects nothere.csv --pairs P.csv",
                    "nothere.csv: cannot open: No such file or directory");
    expect_rejected("--rects R.csv --pairs nothere.csv",
                    "nothere.csv: cannot open: No such file or directory");
    const run_result r = s.run("collide --rects R.csv --pairs P.csv --out nodir/v.txt");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "obbsat: nodir/v.txt: cannot create a temporary file beside it: No such "
                     "file or directory\n");
}

TEST_F(bad_input, a_bogus_obbsat_backend_is_rejected) {
    expect_rejected("--rects R.csv --pairs P.csv",
                    "OBBSAT_BACKEND=bogus names no backend (expected auto, scalar, sse2, avx2 "
                    "or avx512)",
                    "OBBSAT_BACKEND=bogus");
}

TEST_F(bad_input, a_backend_this_cpu_lacks_is_rejected) {
    bool tested = false;
    for (const backend b : obbsat::compiled_backends()) {
        if (obbsat::cpu_supports(b)) {
            continue;
        }
        const std::string name = obbsat::backend_name(b);
        expect_rejected("--rects R.csv --pairs P.csv --backend " + name,
                        "backend " + name + " needs instructions this CPU (or its OS) does not provide");
        expect_rejected("--rects R.csv --pairs P.csv",
                        "OBBSAT_BACKEND=" + name + ": this CPU or build cannot run that backend",
                        "OBBSAT_BACKEND=" + name);
        tested = true;
    }
    if (!tested) {
        GTEST_SKIP() << "this CPU runs every compiled backend";
    }
}

TEST_F(bad_input, a_negative_half_extent_in_a_pose_names_file_line_and_field) {
    write_file(s.file("neg.csv"), "# poses\n" + unit_pose + "0,0,1,1,0.5\n\n" + unit_pose + "# c\n" +
                                      "3,4,1,-1,1,0\n");
    expect_rejected("--poses neg.csv --pairs P.csv",
                    "neg.csv:7: field 4 (hy): '-1' is negative (a half extent must be >= 0)");
    write_file(s.file("neg5.csv"), "-0x1p-3,0,-0x1p-3,1,2\n");
    expect_rejected("--poses neg5.csv --pairs P.csv",
                    "neg5.csv:1: field 3 (hx): '-0x1p-3' is negative (a half extent must be >= 0)");
}

TEST_F(bad_input, a_zero_rotation_vector_is_rejected) {
    write_file(s.file("zero.csv"), unit_pose + "1,1,1,1, 0 ,-0x0p+0\r\n");
    expect_rejected("--poses zero.csv --pairs P.csv",
                    "zero.csv:2: fields 5 and 6 (c, s): '0', '-0x0p+0' make the rotation vector (0, 0), "
                    "which has no direction");
}

TEST_F(bad_input, a_non_finite_or_overflowing_pose_value_is_rejected) {
    write_file(s.file("nan.csv"), unit_pose + "0,0,1,1,nan,0\n");
    expect_rejected("--poses nan.csv --pairs P.csv", "nan.csv:2: field 5 (c): 'nan' is not finite");
    write_file(s.file("inf.csv"), "0,0,1,1,-inf\n");
    expect_rejected("--poses inf.csv --pairs P.csv", "inf.csv:1: field 5 (angle): '-inf' is not finite");
    write_file(s.file("big.csv"), unit_pose + unit_pose + "0,0x1p128,1,1,1,0\n");
    expect_rejected("--poses big.csv --pairs P.csv",
                    "big.csv:3: field 2 (cy): '0x1p128' is out of float range (magnitude above "
                    "3.40282347e+38)");
}

TEST_F(bad_input, a_wrong_pose_field_count_is_rejected) {
    const std::string layout = "(cx,cy,hx,hy,angle or cx,cy,hx,hy,c,s)";
    write_file(s.file("four.csv"), "0,0,1,1\n");
    expect_rejected("--poses four.csv --pairs P.csv",
                    "four.csv:1: expected 5 or 6 comma-separated fields " + layout + ", found 4");
    write_file(s.file("seven.csv"), unit_pose + "0,0,1,1,1,0,0\n");
    expect_rejected("--poses seven.csv --pairs P.csv",
                    "seven.csv:2: expected 5 or 6 comma-separated fields " + layout + ", found 7");
    // A corner file given as poses.
    expect_rejected("--poses R.csv --pairs P.csv",
                    "R.csv:2: expected 5 or 6 comma-separated fields " + layout + ", found 8");
}

TEST_F(bad_input, trailing_garbage_in_a_pose_field_is_rejected) {
    write_file(s.file("junk.csv"), unit_pose + "0,0,1,1,1,0;\n");
    expect_rejected("--poses junk.csv --pairs P.csv", "junk.csv:2: field 6 (s): '0;' is not a number");
    write_file(s.file("rad.csv"), "0,0,1,1,0.25rad\n");
    expect_rejected("--poses rad.csv --pairs P.csv", "rad.csv:1: field 5 (angle): '0.25rad' is not a number");
}

TEST_F(bad_input, pair_indices_are_checked_against_the_pose_count) {
    write_file(s.file("far.csv"), "0,1\n\n1,2\n");
    expect_rejected("--poses Q.csv --pairs far.csv",
                    "far.csv:3: index 2 is out of range: Q.csv holds 2 rectangles (indices 0 to 1)");
    write_file(s.file("none.csv"), "# no poses\n");
    expect_rejected("--poses none.csv --pairs P.csv",
                    "P.csv:1: index 0 refers to a rectangle, but none.csv holds none");
}

TEST_F(bad_input, a_bad_pose_line_on_standard_input_is_named_stdin) {
    write_file(s.file("bad_poses.csv"), unit_pose + "0,0,1,1,1\n0,0,1,1,1,0,1\n");
    const run_result r = s.run("collide --poses - --pairs P.csv --out v.txt", "",
                               "< '" + s.file("bad_poses.csv").string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "obbsat: <stdin>:3: expected 5 or 6 comma-separated fields "
                     "(cx,cy,hx,hy,angle or cx,cy,hx,hy,c,s), found 7\n");
    EXPECT_EQ(read_file(s.file("v.txt")), "previous verdicts\n");
}

TEST_F(bad_input, a_missing_pose_file_is_rejected) {
    expect_rejected("--poses nothere.csv --pairs P.csv",
                    "nothere.csv: cannot open: No such file or directory");
}

// ---------------------------------------------------------------------------
// OBBSAT_BACKEND and `obbsat backends`.

TEST(backends_command, lists_every_compiled_backend_and_the_automatic_choice) {
    const scratch s;
    const run_result r = s.run("backends");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    for (const backend b : obbsat::compiled_backends()) {
        char row[64];
        std::snprintf(row, sizeof row, "\n%-8s %5u  %s\n", obbsat::backend_name(b),
                      obbsat::backend_lanes(b), obbsat::cpu_supports(b) ? "runs" : "lacks");
        EXPECT_NE(r.out.find(row), std::string::npos) << row << " not in\n" << r.out;
    }
    EXPECT_NE(r.out.find(std::string("\nauto: ") +
                         obbsat::backend_name(obbsat::best_supported_backend()) +
                         " (best this CPU runs)\n"),
              std::string::npos)
        << r.out;
}

TEST(backends_command, obbsat_backend_forces_the_scalar_backend) {
    const scratch s;
    const run_result r = s.run("backends", "OBBSAT_BACKEND=scalar");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("\nauto: scalar (OBBSAT_BACKEND=scalar)\n"), std::string::npos) << r.out;
}

// Every command checks OBBSAT_BACKEND before it starts, whether or not it
// uses the automatic choice: a value that names no backend is an error, and
// nothing is written.
TEST(program, a_bogus_obbsat_backend_is_an_error_for_every_command) {
    const scratch s;
    write_file(s.file("R.csv"), unit_rect + unit_rect);
    write_file(s.file("P.csv"), "0,1\n");
    for (const std::string args :
         {"collide --rects R.csv --pairs P.csv", "collide --rects R.csv --pairs P.csv --backend scalar",
          "collide --rects R.csv --pairs P.csv --backend auto --out v.txt",
          "draw --rects R.csv --pairs P.csv --select 0 --backend scalar --out d.svg",
          "demo --rects 100 --pairs 100 --reps 1", "accuracy --pairs 10 --reps 1 --json a.json",
          "gen tiles --pairs 10 --out g", "pairs --rects R.csv --out p.csv",
          "gen --scene uniform --boxes 3 --out s.csv"}) {
        for (const std::string value : {"bogus", "AVX2", "scalar,sse2", " "}) {
            const run_result r = s.run(args, "OBBSAT_BACKEND='" + value + "'");
            EXPECT_EQ(r.status, 2) << args << " with " << value;
            EXPECT_EQ(r.err, "obbsat: OBBSAT_BACKEND=" + value +
                                 " names no backend (expected auto, scalar, sse2, avx2 or avx512)\n")
                << args;
            EXPECT_EQ(r.out, "") << args;
            EXPECT_EQ(s.entries(), (std::vector<std::string>{"P.csv", "R.csv"})) << args;
        }
    }
    // Help and the version need no backend.
    EXPECT_EQ(s.run("--version", "OBBSAT_BACKEND=bogus").status, 0);
    EXPECT_EQ(s.run("collide --help", "OBBSAT_BACKEND=bogus").status, 0);
}

TEST(backends_command, a_bogus_obbsat_backend_is_an_error_after_the_list) {
    const scratch s;
    const run_result r = s.run("backends", "OBBSAT_BACKEND=bogus");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("\nscalar "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("auto:"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "obbsat: OBBSAT_BACKEND=bogus names no backend (expected auto, scalar, "
                     "sse2, avx2 or avx512)\n");
}

// ---------------------------------------------------------------------------
// Verdicts: the reference, then every backend byte for byte.

// Rectangles meant to be hard: integer squares that touch along edges and at
// corners (at the origin and at offsets where float spacing is 1/8, 2 and 4),
// rotated rectangles near each other, far from the origin, tiny, huge enough
// for products to overflow, and degenerate ones (points, segments).
struct hard_input {
    std::vector<rect> rects;
    std::vector<pair_index> pairs;
};

rect square(float x, float y, float side, bool clockwise) {
    const point ul{x, y + side}, ur{x + side, y + side}, lr{x + side, y}, ll{x, y};
    // The other winding: UL, UR, LR, LL run counter-clockwise.
    return clockwise ? rect{ul, ur, lr, ll} : rect{ll, lr, ur, ul};
}

rect scaled(const rect& r, float scale, point shift) {
    auto f = [&](point p) { return point{p.x * scale + shift.x, p.y * scale + shift.y}; };
    return rect{f(r.ul), f(r.ur), f(r.lr), f(r.ll)};
}

hard_input make_hard_input() {
    hard_input in;
    obbsat::seeded_random random(20261121);
    auto pair = [&](std::size_t a, std::size_t b) {
        in.pairs.push_back(pair_index{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
    };

    struct grid {
        float origin;
        float side;
    };
    for (const grid g : {grid{0.0f, 1.0f}, grid{1048576.0f, 1.0f}, grid{16777216.0f, 2.0f},
                         grid{-33554432.0f, 4.0f}}) {
        const std::size_t first = in.rects.size();
        constexpr int n = 6;
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                in.rects.push_back(square(g.origin + static_cast<float>(x) * g.side,
                                          g.origin + static_cast<float>(y) * g.side, g.side,
                                          (x + y) % 2 == 0));
            }
        }
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                for (int dy = -2; dy <= 2; ++dy) {
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u >= 0 && v >= 0 && u < n && v < n) {
                            pair(first + static_cast<std::size_t>(y * n + x),
                                 first + static_cast<std::size_t>(v * n + u));
                        }
                    }
                }
            }
        }
    }

    struct cluster {
        double center;
        double spread;
        float scale;
    };
    for (const cluster c : {cluster{0.0, 8.0, 1.0f}, cluster{1.0e7, 8.0, 1.0f},
                            cluster{-3.0e5, 6.0, 1.0f}, cluster{0.0, 8.0, 1e-30f},
                            cluster{0.0, 8.0, 3e18f}}) {
        const std::size_t first = in.rects.size();
        constexpr std::size_t n = 150;
        for (std::size_t i = 0; i < n; ++i) {
            obbsat::pose p;
            p.center = point{random.uniform(0.0f, 1.0f) * static_cast<float>(c.spread),
                             random.uniform(0.0f, 1.0f) * static_cast<float>(c.spread)};
            p.half_extents = point{random.uniform(0.5f, 3.0f), random.uniform(0.5f, 3.0f)};
            p.angle = random.uniform(-3.2f, 3.2f);
            if (i % 25 == 0) {
                p.half_extents = point{0.0f, 0.0f};  // a point
            } else if (i % 25 == 1) {
                p.half_extents.y = 0.0f;  // a segment
            }
            in.rects.push_back(
                scaled(obbsat::corners_of(p), c.scale, point{static_cast<float>(c.center),
                                                             static_cast<float>(c.center)}));
        }
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 1; k <= 6; ++k) {
                pair(first + i, first + (i + k * 7) % n);
            }
        }
    }

    for (int k = 0; k < 300; ++k) {
        pair(random.below(in.rects.size()), random.below(in.rects.size()));
    }
    return in;
}

// Half the rectangles as hex floats, half in shortest-round-trip decimal, with
// a comment, blank lines and CRLF sprinkled in: the reader must be exact for all.
std::string rect_text(const std::vector<rect>& rects) {
    std::string text = "# hard cases\n";
    char line[512];
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const rect& r = rects[i];
        const double v[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
        const char* format = i % 2 == 0 ? "%a,%a,%a,%a,%a,%a,%a,%a"
                                        : "%.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g, %.9g";
        std::snprintf(line, sizeof line, format, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
        text += line;
        text += i % 5 == 0 ? "\r\n" : "\n";
        if (i % 97 == 0) {
            text += "\n";
        }
    }
    return text;
}

std::string pair_text(const std::vector<pair_index>& pairs) {
    std::string text;
    for (const pair_index& p : pairs) {
        text += std::to_string(p.a) + "," + std::to_string(p.b) + "\n";
    }
    return text;
}

std::string reference_verdicts(method m, const std::vector<rect>& rects,
                               const std::vector<pair_index>& pairs) {
    std::string text;
    for (const pair_index& p : pairs) {
        text += reference_collides(m, rects[p.a], rects[p.b]) ? "1\n" : "0\n";
    }
    return text;
}

class verdicts : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        files_ = new scratch();
        const hard_input in = make_hard_input();
        write_file(files_->file("R.csv"), rect_text(in.rects));
        write_file(files_->file("P.csv"), pair_text(in.pairs));
        references_ = new std::vector<std::string>();
        for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            references_->push_back(reference_verdicts(m, in.rects, in.pairs));
        }
        reference_ = &references_->front();
    }
    static void TearDownTestSuite() {
        delete files_;
        delete references_;
        files_ = nullptr;
        references_ = nullptr;
        reference_ = nullptr;
    }

    /// The expected verdict text of method `m`.
    static const std::string& reference_of(method m) {
        return (*references_)[static_cast<std::size_t>(m)];
    }

    static scratch* files_;
    static std::vector<std::string>* references_;
    static const std::string* reference_;  // method sat4, the default
};

scratch* verdicts::files_ = nullptr;
std::vector<std::string>* verdicts::references_ = nullptr;
const std::string* verdicts::reference_ = nullptr;

TEST_F(verdicts, the_hard_input_has_thousands_of_pairs_of_both_kinds) {
    const std::size_t lines = static_cast<std::size_t>(
        std::count(reference_->begin(), reference_->end(), '\n'));
    EXPECT_GT(lines, 4000u);
    const std::size_t ones = static_cast<std::size_t>(
        std::count(reference_->begin(), reference_->end(), '1'));
    EXPECT_GT(ones, lines / 10);
    EXPECT_LT(ones, lines - lines / 10);
}

TEST_F(verdicts, scalar_backend_matches_the_reference_in_process) {
    const run_result r =
        files_->run("collide --rects R.csv --pairs P.csv --backend scalar --out v_scalar.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(read_file(files_->file("v_scalar.txt")), *reference_);
}

TEST_F(verdicts, every_method_on_the_scalar_backend_matches_its_reference) {
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const std::string name = obbsat::method_name(m);
        const run_result r = files_->run("collide --rects R.csv --pairs P.csv --backend scalar "
                                         "--method " + name);
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        EXPECT_EQ(r.out, reference_of(m)) << name;
    }
}

TEST_F(verdicts, methods_differ_on_the_hard_input) {
    // Otherwise --method could be ignored and every test above still pass.
    const auto& all = *references_;
    for (std::size_t i = 1; i < all.size(); ++i) {
        EXPECT_NE(all[i], all[0]) << obbsat::method_name(obbsat::methods_on(obbsat::store_kind::corners)[i]);
    }
}

TEST_F(verdicts, standard_output_and_stdin_give_the_same_bytes) {
    const run_result to_stdout = files_->run("collide --rects R.csv --pairs P.csv");
    ASSERT_EQ(to_stdout.status, 0) << to_stdout.err;
    EXPECT_EQ(to_stdout.out, *reference_);
    const run_result from_stdin = files_->run("collide --rects R.csv --pairs - --threads 0", "",
                                              "< '" + files_->file("P.csv").string() + "'");
    ASSERT_EQ(from_stdin.status, 0) << from_stdin.err;
    EXPECT_EQ(from_stdin.out, *reference_);
}

TEST_F(verdicts, obbsat_backend_scalar_and_an_explicit_backend_win_over_auto) {
    const run_result forced =
        files_->run("collide --rects R.csv --pairs P.csv", "OBBSAT_BACKEND=scalar");
    ASSERT_EQ(forced.status, 0) << forced.err;
    EXPECT_EQ(forced.out, *reference_);
    // An explicit --backend is a request of its own; a valid OBBSAT_BACKEND only steers auto.
    const run_result explicit_backend =
        files_->run("collide --rects R.csv --pairs P.csv --backend scalar", "OBBSAT_BACKEND=sse2");
    ASSERT_EQ(explicit_backend.status, 0) << explicit_backend.err;
    EXPECT_EQ(explicit_backend.out, *reference_);
}

TEST_F(verdicts, a_garbage_obbsat_backend_is_refused_even_beside_an_explicit_backend) {
    const run_result r = files_->run("collide --rects R.csv --pairs P.csv --backend scalar --out v.txt",
                                     "OBBSAT_BACKEND=bogus");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("OBBSAT_BACKEND=bogus names no backend"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(files_->file("v.txt")));
}

TEST_F(verdicts, output_replaces_an_existing_file_on_success) {
    write_file(files_->file("old.txt"), "stale\n");
    const run_result r = files_->run("collide --rects R.csv --pairs P.csv --out old.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(read_file(files_->file("old.txt")), *reference_);
}

TEST_F(verdicts, output_to_a_device_goes_straight_to_it) {
    const run_result r = files_->run("collide --rects R.csv --pairs P.csv --out /dev/null");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    const run_result to_stdout = files_->run("collide --rects R.csv --pairs P.csv --out /dev/stdout");
    ASSERT_EQ(to_stdout.status, 0) << to_stdout.err;
    EXPECT_EQ(to_stdout.out, *reference_);
}

TEST_F(verdicts, empty_pair_files_give_empty_output) {
    write_file(files_->file("none.csv"), "# no pairs\n\n");
    write_file(files_->file("empty_rects.csv"), "");
    for (const char* rects : {"R.csv", "empty_rects.csv"}) {
        const run_result r = files_->run(std::string("collide --rects ") + rects +
                                         " --pairs none.csv --out empty.txt");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(fs::exists(files_->file("empty.txt")));
        EXPECT_EQ(read_file(files_->file("empty.txt")), "");
    }
}

struct backend_run {
    method test;
    backend use;
    unsigned threads;
};

// Names the parameter in test listings instead of dumping its bytes.
void PrintTo(const backend_run& run, std::ostream* os) {
    *os << obbsat::method_name(run.test) << " on " << obbsat::backend_name(run.use) << " at "
        << run.threads << " thread(s)";
}

std::string backend_run_name(const ::testing::TestParamInfo<backend_run>& info) {
    return std::string(obbsat::method_name(info.param.test)) + "_" +
           obbsat::backend_name(info.param.use) + "_" + std::to_string(info.param.threads) +
           "_threads";
}

// Every method on every backend (those this CPU lacks are skipped when run).
std::vector<backend_run> every_backend_run() {
    std::vector<backend_run> runs;
    const std::pair<backend, unsigned> backends[] = {
        {backend::scalar, 2}, {backend::sse2, 1},   {backend::sse2, 2},
        {backend::avx2, 1},   {backend::avx2, 2},   {backend::avx512, 1},
        {backend::avx512, 2}, {backend::automatic, 2}};
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        for (const auto& [use, threads] : backends) {
            runs.push_back(backend_run{m, use, threads});
        }
    }
    return runs;
}

class verdicts_per_backend : public verdicts, public ::testing::WithParamInterface<backend_run> {};

TEST_P(verdicts_per_backend, identical_bytes_to_the_reference) {
    const backend_run run = GetParam();
    if (!obbsat::cpu_supports(run.use) && run.use != backend::automatic) {
        GTEST_SKIP() << "this CPU or build lacks " << obbsat::backend_name(run.use);
    }
    const std::string name = obbsat::backend_name(run.use);
    const std::string test = obbsat::method_name(run.test);
    const std::string out = "v_" + test + "_" + name + "_" + std::to_string(run.threads) + ".txt";
    const run_result r = files_->run("collide --rects R.csv --pairs P.csv --method " + test +
                                     " --backend " + name + " --threads " +
                                     std::to_string(run.threads) + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_file(files_->file(out)), reference_of(run.test));
}

INSTANTIATE_TEST_SUITE_P(every_backend, verdicts_per_backend,
                         ::testing::ValuesIn(every_backend_run()), backend_run_name);

// ---------------------------------------------------------------------------
// Poses (--poses): every method on poses against its scalar reference.

// Poses meant to be hard, each with the line that writes it: squares that touch
// along edges and at corners, written with every axis-aligned rotation vector
// and with vectors of length 2 and 1/8 (half extents scaled to match, so the
// same square); squares turned by the integer vector (3, 4), neighbours exactly
// touching; random poses near each other, far from the origin, tiny, huge,
// points and segments, half of them as angle lines (5 fields).
struct hard_pose_input {
    std::string text;
    std::vector<rect_pose> poses;  // what the program must read from `text`
    std::vector<pair_index> pairs;
};

hard_pose_input make_hard_pose_input() {
    hard_pose_input in;
    in.text = "# hard cases: cx,cy,hx,hy,c,s or cx,cy,hx,hy,angle\n";
    obbsat::seeded_random random(20261122);
    char line[256];
    auto add = [&](const rect_pose& p, bool hex) {
        const char* format = hex ? "%a,%a,%a,%a,%a,%a" : "%.9g, %.9g, %.9g, %.9g, %.9g, %.9g";
        std::snprintf(line, sizeof line, format, static_cast<double>(p.center.x),
                      static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                      static_cast<double>(p.half_extents.y), static_cast<double>(p.rotation.x),
                      static_cast<double>(p.rotation.y));
        in.text += line;
        in.text += in.poses.size() % 5 == 0 ? "\r\n" : "\n";
        in.poses.push_back(p);
    };
    auto add_angle = [&](const obbsat::pose& p) {
        const char* format = in.poses.size() % 3 == 0 ? "%a,%a,%a,%a,%a" : "%.9g,%.9g,%.9g,%.9g,%.9g";
        std::snprintf(line, sizeof line, format, static_cast<double>(p.center.x),
                      static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                      static_cast<double>(p.half_extents.y), static_cast<double>(p.angle));
        in.text += line;
        in.text += "\n";
        in.poses.push_back(obbsat::rect_pose_of(p));
    };
    auto pair = [&](std::size_t a, std::size_t b) {
        in.pairs.push_back(pair_index{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
    };
    auto neighbours = [&](std::size_t first, int n) {
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                for (int dy = -2; dy <= 2; ++dy) {
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u >= 0 && v >= 0 && u < n && v < n) {
                            pair(first + static_cast<std::size_t>(y * n + x),
                                 first + static_cast<std::size_t>(v * n + u));
                        }
                    }
                }
            }
        }
    };

    struct grid {
        float origin;
        float half;
    };
    // Rotation vectors that give the same square when the half extents are
    // divided by their length.
    const point rotations[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {2, 0}, {0, -0.125f}};
    for (const grid g : {grid{0.0f, 0.5f}, grid{1048576.0f, 0.5f}, grid{16777216.0f, 2.0f},
                         grid{-33554432.0f, 4.0f}}) {
        const std::size_t first = in.poses.size();
        constexpr int n = 6;
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const point r = rotations[static_cast<std::size_t>(y * n + x) % 6];
                const float length = std::max(std::abs(r.x), std::abs(r.y));
                const float h = g.half / length;
                add(rect_pose{{g.origin + static_cast<float>(2 * x) * g.half,
                               g.origin + static_cast<float>(2 * y) * g.half},
                              {h, h},
                              r},
                    (x + y) % 2 == 0);
            }
        }
        neighbours(first, n);
    }
    // Turned by (3, 4): local x along (3, 4), local y along (-4, 3), each
    // half extent 1 spans 5 units; neighbours at (6, 8) and (-8, 6) touch.
    for (const float origin : {0.0f, 4096.0f, -1048576.0f}) {
        const std::size_t first = in.poses.size();
        constexpr int n = 5;
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const point center{origin + static_cast<float>(6 * x - 8 * y),
                                   origin + static_cast<float>(8 * x + 6 * y)};
                add(rect_pose{center, {1, 1}, {3, 4}}, x % 2 == 0);
            }
        }
        neighbours(first, n);
    }

    // Unit squares a few ulps apart, and a few ulps overlapping, along x: the
    // float test sees every gap, a guarded test cannot.
    for (int k = -4; k <= 12; ++k) {
        const float step = 0x1p-23f * static_cast<float>(k);
        const point r = rotations[static_cast<std::size_t>(k + 4) % 6];
        const float h = 0.5f / std::max(std::abs(r.x), std::abs(r.y));
        const std::size_t first = in.poses.size();
        add(rect_pose{{0.0f, 0.0f}, {0.5f, 0.5f}, {1, 0}}, k % 2 == 0);
        add(rect_pose{{1.0f + step, 0.25f * static_cast<float>(k % 3)}, {h, h}, r}, k % 2 != 0);
        pair(first, first + 1);
        pair(first + 1, first);
    }

    struct cluster {
        float center;
        float spread;
        float scale;
    };
    for (const cluster c : {cluster{0.0f, 8.0f, 1.0f}, cluster{1.0e7f, 8.0f, 1.0f},
                            cluster{-3.0e5f, 6.0f, 1.0f}, cluster{0.0f, 8.0f, 1e-30f},
                            cluster{0.0f, 8.0f, 3e18f}}) {
        const std::size_t first = in.poses.size();
        constexpr std::size_t n = 150;
        for (std::size_t i = 0; i < n; ++i) {
            obbsat::pose p;
            p.center = point{c.center + random.uniform(0.0f, c.spread) * c.scale,
                             c.center + random.uniform(0.0f, c.spread) * c.scale};
            p.half_extents =
                point{random.uniform(0.5f, 3.0f) * c.scale, random.uniform(0.5f, 3.0f) * c.scale};
            p.angle = random.uniform(-3.2f, 3.2f);
            if (i % 25 == 0) {
                p.half_extents = point{0.0f, 0.0f};  // a point
            } else if (i % 25 == 1) {
                p.half_extents.y = 0.0f;  // a segment
            }
            if (i % 2 == 0) {
                add_angle(p);
            } else {
                add(obbsat::rect_pose_of(p), i % 4 == 1);
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 1; k <= 6; ++k) {
                pair(first + i, first + (i + k * 7) % n);
            }
        }
    }

    for (int k = 0; k < 300; ++k) {
        pair(random.below(in.poses.size()), random.below(in.poses.size()));
    }
    return in;
}

std::string pose_reference_verdicts(method m, const std::vector<rect_pose>& poses,
                                    const std::vector<pair_index>& pairs) {
    const obbsat::pose_reference_fn reference = obbsat::pose_method_reference(m);
    std::string text;
    for (const pair_index& p : pairs) {
        text += reference(poses[p.a], poses[p.b]) ? "1\n" : "0\n";
    }
    return text;
}

class pose_verdicts : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        files_ = new scratch();
        const hard_pose_input in = make_hard_pose_input();
        write_file(files_->file("Q.csv"), in.text);
        write_file(files_->file("P.csv"), pair_text(in.pairs));
        references_ = new std::vector<std::string>(obbsat::method_count);
        for (const method m : obbsat::methods_on(store_kind::poses)) {
            (*references_)[static_cast<std::size_t>(m)] = pose_reference_verdicts(m, in.poses, in.pairs);
        }
    }
    static void TearDownTestSuite() {
        delete files_;
        delete references_;
        files_ = nullptr;
        references_ = nullptr;
    }

    /// The expected verdict text of method `m` on the hard poses.
    static const std::string& reference_of(method m) { return (*references_)[static_cast<std::size_t>(m)]; }

    static scratch* files_;
    static std::vector<std::string>* references_;  // indexed by method; empty where it does not run
};

scratch* pose_verdicts::files_ = nullptr;
std::vector<std::string>* pose_verdicts::references_ = nullptr;

TEST_F(pose_verdicts, the_hard_input_has_thousands_of_pairs_of_both_kinds) {
    const std::string& local = reference_of(method::local);
    const std::size_t lines = static_cast<std::size_t>(std::count(local.begin(), local.end(), '\n'));
    EXPECT_GT(lines, 4000u);
    const std::size_t ones = static_cast<std::size_t>(std::count(local.begin(), local.end(), '1'));
    EXPECT_GT(ones, lines / 10);
    EXPECT_LT(ones, lines - lines / 10);
}

TEST_F(pose_verdicts, the_default_method_on_poses_is_local) {
    const run_result r = files_->run("collide --poses Q.csv --pairs P.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, reference_of(method::local));
}

TEST_F(pose_verdicts, methods_on_poses_differ_on_the_hard_input) {
    // Otherwise --method could be ignored on poses and every test here still pass.
    const std::vector<method> methods = obbsat::methods_on(store_kind::poses);
    ASSERT_GE(methods.size(), 2u);
    bool some_differ = false;
    for (const method m : methods) {
        some_differ = some_differ || reference_of(m) != reference_of(methods.front());
    }
    EXPECT_TRUE(some_differ);
}

TEST_F(pose_verdicts, poses_and_pairs_read_from_standard_input_give_the_same_bytes) {
    const run_result poses_piped = files_->run("collide --poses - --pairs P.csv --method local", "",
                                               "< '" + files_->file("Q.csv").string() + "'");
    ASSERT_EQ(poses_piped.status, 0) << poses_piped.err;
    EXPECT_EQ(poses_piped.out, reference_of(method::local));
    const run_result pairs_piped = files_->run("collide --poses Q.csv --pairs - --threads 0", "",
                                               "< '" + files_->file("P.csv").string() + "'");
    ASSERT_EQ(pairs_piped.status, 0) << pairs_piped.err;
    EXPECT_EQ(pairs_piped.out, reference_of(method::local));
    const run_result through_a_pipe =
        files_->run_piped("Q.csv", "collide --poses - --pairs P.csv --out v_pipe.txt");
    ASSERT_EQ(through_a_pipe.status, 0) << through_a_pipe.err;
    EXPECT_EQ(read_file(files_->file("v_pipe.txt")), reference_of(method::local));
}

// Angle lines mean what obbsat::rect_pose_of(pose) makes of them: the same
// verdicts as the six-field lines it returns, written exactly.
TEST_F(pose_verdicts, angle_lines_equal_their_rotation_vectors) {
    std::string angles;
    std::string vectors;
    std::string pairs;
    char line[256];
    obbsat::seeded_random random(77);
    constexpr int n = 200;
    for (int i = 0; i < n; ++i) {
        const obbsat::pose p{{random.uniform(0.0f, 6.0f), random.uniform(0.0f, 6.0f)},
                             {random.uniform(0.0f, 2.0f), random.uniform(0.0f, 2.0f)},
                             random.uniform(-7.0f, 7.0f)};
        std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g\n", static_cast<double>(p.center.x),
                      static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                      static_cast<double>(p.half_extents.y), static_cast<double>(p.angle));
        angles += line;
        const rect_pose r = obbsat::rect_pose_of(p);
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a\n", static_cast<double>(r.center.x),
                      static_cast<double>(r.center.y), static_cast<double>(r.half_extents.x),
                      static_cast<double>(r.half_extents.y), static_cast<double>(r.rotation.x),
                      static_cast<double>(r.rotation.y));
        vectors += line;
        for (int k = 1; k <= 5; ++k) {
            pairs += std::to_string(i) + "," + std::to_string((i + 3 * k) % n) + "\n";
        }
    }
    write_file(files_->file("angles.csv"), angles);
    write_file(files_->file("vectors.csv"), vectors);
    write_file(files_->file("angle_pairs.csv"), pairs);
    for (const method m : obbsat::methods_on(store_kind::poses)) {
        const std::string name = obbsat::method_name(m);
        const run_result from_angles =
            files_->run("collide --poses angles.csv --pairs angle_pairs.csv --method " + name);
        const run_result from_vectors =
            files_->run("collide --poses vectors.csv --pairs angle_pairs.csv --method " + name);
        ASSERT_EQ(from_angles.status, 0) << name << ": " << from_angles.err;
        ASSERT_EQ(from_vectors.status, 0) << name << ": " << from_vectors.err;
        EXPECT_EQ(from_angles.out, from_vectors.out) << name;
        EXPECT_NE(from_angles.out.find('1'), std::string::npos) << name;
        EXPECT_NE(from_angles.out.find('0'), std::string::npos) << name;
    }
}

TEST_F(pose_verdicts, empty_pose_and_pair_files_give_empty_output) {
    write_file(files_->file("no_pairs.csv"), "# no pairs\n");
    write_file(files_->file("no_poses.csv"), "\n# none\n");
    for (const char* poses : {"Q.csv", "no_poses.csv"}) {
        const run_result r = files_->run(std::string("collide --poses ") + poses +
                                         " --pairs no_pairs.csv --out empty.txt");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(fs::exists(files_->file("empty.txt")));
        EXPECT_EQ(read_file(files_->file("empty.txt")), "");
    }
}

// Every method on poses on every backend (those this CPU lacks are skipped).
std::vector<backend_run> every_pose_backend_run() {
    std::vector<backend_run> runs;
    const std::pair<backend, unsigned> backends[] = {
        {backend::scalar, 1}, {backend::scalar, 2}, {backend::sse2, 1},   {backend::sse2, 2},
        {backend::avx2, 1},   {backend::avx2, 2},   {backend::avx512, 1}, {backend::avx512, 2},
        {backend::automatic, 2}};
    for (const method m : obbsat::methods_on(store_kind::poses)) {
        for (const auto& [use, threads] : backends) {
            runs.push_back(backend_run{m, use, threads});
        }
    }
    return runs;
}

class pose_verdicts_per_backend : public pose_verdicts, public ::testing::WithParamInterface<backend_run> {};

TEST_P(pose_verdicts_per_backend, identical_bytes_to_the_reference) {
    const backend_run run = GetParam();
    if (!obbsat::cpu_supports(run.use) && run.use != backend::automatic) {
        GTEST_SKIP() << "this CPU or build lacks " << obbsat::backend_name(run.use);
    }
    const std::string name = obbsat::backend_name(run.use);
    const std::string test = obbsat::method_name(run.test);
    const std::string out = "v_" + test + "_" + name + "_" + std::to_string(run.threads) + ".txt";
    const run_result r = files_->run("collide --poses Q.csv --pairs P.csv --method " + test + " --backend " +
                                     name + " --threads " + std::to_string(run.threads) + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(read_file(files_->file(out)), reference_of(run.test));
}

INSTANTIATE_TEST_SUITE_P(every_backend, pose_verdicts_per_backend,
                         ::testing::ValuesIn(every_pose_backend_run()), backend_run_name);

// The labelled case families, when they are beside the project: the program's
// verdicts must be the scalar reference's on exactly the floats in the files.
TEST(shared_cases, program_verdicts_equal_the_reference_on_every_family) {
    const std::optional<std::string> root = obbsat::test_support::shared_cases_folder();
    if (!root) {
        GTEST_SKIP() << obbsat::test_support::shared_cases_missing();
    }
    const scratch s;
    std::size_t families = 0;
    for (const auto& entry : fs::directory_iterator(*root)) {
        const fs::path rects_path = entry.path() / "rects.csv";
        const fs::path pairs_path = entry.path() / "pairs.csv";
        if (!fs::exists(rects_path) || !fs::exists(pairs_path)) {
            continue;
        }
        const obbsat::rect_soa rects = obbsat::io::read_rects_file(rects_path.string());
        std::vector<pair_index> pairs;
        {
            const obbsat::io::input_file file(pairs_path.string());
            obbsat::io::line_reader lines(file.get(), file.name());
            obbsat::io::pair_reader reader(lines, rects.size(), rects_path.string());
            std::vector<pair_index> chunk;
            while (reader.read_chunk(chunk, 1 << 16)) {
                pairs.insert(pairs.end(), chunk.begin(), chunk.end());
            }
        }
        std::string want;
        for (const pair_index& p : pairs) {
            want += obbsat::ref::sat4(rects[p.a], rects[p.b]) ? "1\n" : "0\n";
        }
        const run_result r = s.run("collide --rects '" + rects_path.string() + "' --pairs '" +
                                   pairs_path.string() + "' --threads 2");
        ASSERT_EQ(r.status, 0) << entry.path() << ": " << r.err;
        EXPECT_EQ(r.out, want) << entry.path();
        ++families;
    }
    EXPECT_GT(families, 0u);
}

}  // namespace
