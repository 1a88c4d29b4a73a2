// --precision double in the program: the double readers (every digit of a
// double kept, hex too, the float readers' errors with file and line), and
// collide, draw and pairs run as a user runs them on pairs at UTM-like and
// larger coordinates, where rounding to float32 flips verdicts that the double
// methods get right.
#include "io/csv_input.hpp"
#include "program_runner.hpp"

#include <obbsat/find_pairs.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using obbsat::point64;
using obbsat::rect64;
using obbsat::rect_pose64;
using obbsat::cli_test::lines_of;
using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;
using obbsat::io::input_error;
using obbsat::io::line_reader;
using obbsat::oracle::contact;

// The shortest text that reads back to `v`.
std::string text_of(double v) {
    char text[40];
    return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

std::string pose_line(const rect_pose64& p) {
    return text_of(p.center.x) + "," + text_of(p.center.y) + "," + text_of(p.half_extents.x) + "," +
           text_of(p.half_extents.y) + "," + text_of(p.rotation.x) + "," + text_of(p.rotation.y) + "\n";
}

std::string hex_of(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%a", v);
    return text;
}

rect64 corners_of(const rect_pose64& p) {
    const double c = p.rotation.x, s = p.rotation.y, hx = p.half_extents.x, hy = p.half_extents.y;
    auto at = [&](double a, double b) { return point64{p.center.x + a * c - b * s, p.center.y + a * s + b * c}; };
    return rect64{at(-hx, hy), at(hx, hy), at(hx, -hy), at(-hx, -hy)};
}

std::string rect_line(const rect64& r) {
    std::string line;
    for (const point64& q : {r.ul, r.ur, r.lr, r.ll}) {
        line += (line.empty() ? "" : ",") + text_of(q.x) + "," + text_of(q.y);
    }
    return line + "\n";
}

// Pairs of axis-aligned footprints at UTM-like coordinates, B beside A along x
// at a gap of a millimetre, a few double ulps or none, either way: float32 lies
// 0.03 to 0.5 m apart there, so its rounding moves many of them across contact.
std::vector<rect_pose64> utm_footprints() {
    std::vector<rect_pose64> poses;
    const double bases[] = {312345.678, 500000.125, 4123456.789, 5999999.5};
    const double gaps[] = {0.0, 1e-3, -1e-3, 2e-2, -2e-2};
    for (const double base : bases) {
        for (const double gap : gaps) {
            for (const int ulps : {0, 1, -1, 3}) {
                const rect_pose64 a{{base, base + 1234.5}, {10.0, 5.0}, {1.0, 0.0}};
                double bx = a.center.x + 20.0 + gap;
                for (int k = 0; k < std::abs(ulps); ++k) {
                    bx = std::nextafter(bx, ulps > 0 ? INFINITY : -INFINITY);
                }
                poses.push_back(a);
                poses.push_back(rect_pose64{{bx, a.center.y + 2.0}, {10.0, 5.0}, {1.0, 0.0}});
            }
        }
    }
    return poses;
}

std::string pair_lines(std::size_t pairs) {
    std::string text;
    for (std::size_t i = 0; i < pairs; ++i) {
        text += std::to_string(2 * i) + "," + std::to_string(2 * i + 1) + "\n";
    }
    return text;
}

template <class Shape>
std::string truth_of(const std::vector<Shape>& shapes) {
    std::string text;
    for (std::size_t i = 0; i + 1 < shapes.size(); i += 2) {
        text += obbsat::oracle::classify(shapes[i], shapes[i + 1]) == contact::separated ? "0\n" : "1\n";
    }
    return text;
}

std::size_t lines_differing(const std::string& a, const std::string& b) {
    const auto la = lines_of(a), lb = lines_of(b);
    std::size_t differ = la.size() == lb.size() ? 0 : std::max(la.size(), lb.size());
    for (std::size_t i = 0; i < std::min(la.size(), lb.size()); ++i) {
        differ += la[i] != lb[i];
    }
    return differ;
}

// ---------------------------------------------------------------------------
// The readers.

TEST(double_input, keeps_every_digit_of_a_double_and_reads_hex) {
    const std::string text = "500000.123456789,6000000.000000001,10.25,0.1,0.6,0.8\n"
                             "0x1.e848p+18,-0x1.6e36p+22,0x1p-1074,1e300,1,0\n"
                             "1,2,3,4,0.5\n";
    line_reader lines(std::string_view(text), "p.csv");
    const obbsat::pose_records64 poses = obbsat::io::read_pose_records64(lines);
    ASSERT_EQ(poses.size(), 3u);
    EXPECT_EQ(poses[0].center.x, 500000.123456789);
    EXPECT_EQ(poses[0].center.y, 6000000.000000001);
    EXPECT_NE(poses[0].center.y, 6000000.0);  // float32 and a careless reader would lose it
    EXPECT_NE(static_cast<double>(static_cast<float>(poses[0].center.x)), poses[0].center.x);
    EXPECT_EQ(poses[0].half_extents.y, 0.1);
    EXPECT_EQ(poses[1].center.x, 500000.0);
    EXPECT_EQ(poses[1].center.y, -0x1.6e36p+22);
    EXPECT_EQ(poses[1].half_extents.x, 0x1p-1074);  // the least subnormal double
    EXPECT_EQ(poses[1].half_extents.y, 1e300);      // beyond float range, a double
    EXPECT_EQ(poses[2].rotation.x, std::cos(0.5));
    EXPECT_EQ(poses[2].rotation.y, std::sin(0.5));

    const std::string corners = "ulx,uly,urx,ury,lrx,lry,llx,lly\n"
                                "500000.1,1,500001.1,1,500001.1,0,500000.1,0\n";
    line_reader corner_lines(std::string_view(corners), "r.csv");
    const obbsat::rect_records64 rects = obbsat::io::read_rect_records64(corner_lines);
    ASSERT_EQ(rects.size(), 1u);
    EXPECT_EQ(rects[0].ul.x, 500000.1);
    EXPECT_EQ(rects[0].ur.x, 500001.1);
}

std::string pose64_error(const std::string& text) {
    line_reader lines(std::string_view(text), "p.csv");
    try {
        obbsat::io::read_pose_records64(lines);
    } catch (const input_error& e) {
        return e.what();
    }
    return "no error";
}

std::string rect64_error(const std::string& text) {
    line_reader lines(std::string_view(text), "r.csv");
    try {
        obbsat::io::read_rect_records64(lines);
    } catch (const input_error& e) {
        return e.what();
    }
    return "no error";
}

TEST(double_input, errors_name_file_line_and_field_as_for_float) {
    const std::string good = "1,2,3,4,1,0\n# a comment\n";
    EXPECT_EQ(pose64_error(good + "1e400,2,3,4,1,0\n"),
              "p.csv:3: field 1 (cx): '1e400' is out of double range (magnitude above 1.7976931348623157e+308)");
    EXPECT_EQ(pose64_error(good + "1,nan,3,4,1,0\n"), "p.csv:3: field 2 (cy): 'nan' is not finite");
    EXPECT_EQ(pose64_error(good + "1,2,inf,4,1,0\n"), "p.csv:3: field 3 (hx): 'inf' is not finite");
    EXPECT_EQ(pose64_error(good + "1,2,3,-1e-300,1,0\n"),
              "p.csv:3: field 4 (hy): '-1e-300' is negative (a half extent must be >= 0)");
    EXPECT_EQ(pose64_error(good + "1,2,3,4,0,-0\n"),
              "p.csv:3: fields 5 and 6 (c, s): '0', '-0' make the rotation vector (0, 0), which has no direction");
    EXPECT_EQ(pose64_error(good + "1,2,3,4,1,x\n"), "p.csv:3: field 6 (s): 'x' is not a number");
    EXPECT_EQ(pose64_error(good + "1,2,3\n"),
              "p.csv:3: expected 5 or 6 comma-separated fields (cx,cy,hx,hy,angle or cx,cy,hx,hy,c,s), found 3");
    EXPECT_EQ(pose64_error(good + "1,2,3,4,1,\n"), "p.csv:3: field 6 (s) is empty");
    // A value that rounds to a double subnormal or to zero is accepted, as in float.
    EXPECT_EQ(pose64_error(good + "1e-330,2,3,4,1,0\n"), "no error");
    EXPECT_EQ(rect64_error("0,0,1,0,1,1,0,1\n0,0,1,0,1,1,0,-nan\n"),
              "r.csv:2: field 8 (lly): '-nan' is not finite");
    EXPECT_EQ(rect64_error("x,y,a,b,c,d,e,f\n"),
              "r.csv:1: expected the header 'ulx,uly,urx,ury,lrx,lry,llx,lly' or a rectangle, found "
              "'x,y,a,b,c,d,e,f'");
}

// ---------------------------------------------------------------------------
// collide --precision double.

TEST(double_precision, utm_pairs_that_float32_rounding_flips_are_answered_exactly) {
    const scratch s;
    const std::vector<rect_pose64> poses = utm_footprints();
    std::string pose_text = "cx,cy,hx,hy,c,s\n";
    std::string hex_text;
    std::string rect_text;
    std::vector<rect64> rects;
    for (const rect_pose64& p : poses) {
        pose_text += pose_line(p);
        hex_text += hex_of(p.center.x) + "," + hex_of(p.center.y) + "," + hex_of(p.half_extents.x) + "," +
                    hex_of(p.half_extents.y) + "," + hex_of(p.rotation.x) + "," + hex_of(p.rotation.y) + "\n";
        rects.push_back(corners_of(p));
        rect_text += rect_line(rects.back());
    }
    write_file(s.file("p.csv"), pose_text);
    write_file(s.file("hex.csv"), hex_text);
    write_file(s.file("r.csv"), rect_text);
    write_file(s.file("pairs.csv"), pair_lines(poses.size() / 2));
    const std::string truth = truth_of(poses);
    ASSERT_EQ(truth, truth_of(rects));  // axis-aligned: the corners are exact

    const run_result exact = s.run("collide --poses p.csv --pairs pairs.csv --precision double --method exact");
    ASSERT_EQ(exact.status, 0) << exact.err;
    EXPECT_EQ(exact.out, truth);
    EXPECT_EQ(exact.err, "");
    // Decimal and hex give the same doubles, so the same verdicts.
    const run_result hex = s.run("collide --poses hex.csv --pairs pairs.csv --precision double --method exact");
    EXPECT_EQ(hex.out, truth);
    // local is the default on poses; on these axis-aligned pairs it is exact too.
    const run_result local = s.run("collide --poses p.csv --pairs pairs.csv --precision double");
    EXPECT_EQ(local.out, truth);
    const run_result corners =
        s.run("collide --rects r.csv --pairs pairs.csv --precision double --out v.txt --header");
    ASSERT_EQ(corners.status, 0) << corners.err;
    EXPECT_EQ(read_file(s.file("v.txt")), "verdict\n" + truth);  // exact is the default on double corners
    // Every backend answers the same on double corners (SSE2 runs on every x86-64 CPU).
    for (const char* use : {"scalar", "sse2"}) {
        const run_result on = s.run(std::string("collide --rects r.csv --pairs pairs.csv --precision double --backend ") + use);
        ASSERT_EQ(on.status, 0) << use << ": " << on.err;
        EXPECT_EQ(on.out, truth) << use;
    }
    // conservative never misses a collision, on either store.
    for (const char* input : {"--poses p.csv", "--rects r.csv"}) {
        const run_result c = s.run(std::string("collide ") + input +
                                   " --pairs pairs.csv --precision double --method conservative");
        ASSERT_EQ(c.status, 0) << c.err;
        const auto said = lines_of(c.out), meant = lines_of(truth);
        ASSERT_EQ(said.size(), meant.size());
        for (std::size_t i = 0; i < said.size(); ++i) {
            EXPECT_FALSE(meant[i] == "1" && said[i] == "0") << input << " pair " << i;
        }
    }

    // The same files at float precision: the rounding flips some verdicts.
    const run_result rounded = s.run("collide --poses p.csv --pairs pairs.csv --method exact");
    ASSERT_EQ(rounded.status, 0) << rounded.err;
    EXPECT_GT(lines_differing(rounded.out, truth), 0u);
    const run_result rounded_corners = s.run("collide --rects r.csv --pairs pairs.csv --method exact");
    EXPECT_GT(lines_differing(rounded_corners.out, truth), 0u);
}

TEST(double_precision, refuses_methods_that_do_not_run_on_doubles_before_reading) {
    const scratch s;
    write_file(s.file("pairs.csv"), "0,1\n");
    const run_result sat4 = s.run("collide --rects missing.csv --pairs pairs.csv --precision double --method sat4");
    EXPECT_EQ(sat4.status, 2);
    EXPECT_EQ(sat4.err,
              "obbsat: collide: --method sat4 does not run on corners (--rects) with --precision double; the "
              "methods on double corners are conservative, exact (see 'obbsat collide --help')\n");
    const run_result local = s.run("collide --rects missing.csv --pairs pairs.csv --precision double --method local");
    EXPECT_EQ(local.status, 2);
    EXPECT_NE(local.err.find("--method local does not run on corners (--rects) with --precision double"),
              std::string::npos)
        << local.err;
    const run_result on_poses =
        s.run("collide --poses missing.csv --pairs pairs.csv --precision double --method sat4_double");
    EXPECT_EQ(on_poses.status, 2);
    EXPECT_NE(on_poses.err.find("sat4_double does not run on poses (--poses) with --precision double"),
              std::string::npos)
        << on_poses.err;
    const run_result word = s.run("collide --poses missing.csv --pairs pairs.csv --precision quad");
    EXPECT_EQ(word.status, 2);
    EXPECT_NE(word.err.find("--precision: unknown precision 'quad' (expected float or double)"), std::string::npos);
    EXPECT_EQ(s.entries(), std::vector<std::string>{"pairs.csv"});
}

TEST(double_precision, bad_input_names_file_and_line_and_leaves_out_untouched) {
    const scratch s;
    write_file(s.file("pairs.csv"), "0,1\n");
    write_file(s.file("v.txt"), "old\n");
    const struct {
        const char* line;
        const char* message;
    } cases[] = {
        {"500000,1,nan,1,1,0", "p.csv:3: field 3 (hx): 'nan' is not finite"},
        {"500000,1,1,-0.001,1,0", "p.csv:3: field 4 (hy): '-0.001' is negative (a half extent must be >= 0)"},
        {"500000,1,1,1,0,0", "p.csv:3: fields 5 and 6 (c, s): '0', '0' make the rotation vector (0, 0)"},
        {"1e999,1,1,1,1,0", "p.csv:3: field 1 (cx): '1e999' is out of double range"},
    };
    for (const auto& c : cases) {
        write_file(s.file("p.csv"), std::string("500000.5,1,1,1,1,0\n\n") + c.line + "\n");
        const run_result r = s.run("collide --poses p.csv --pairs pairs.csv --precision double --out v.txt");
        EXPECT_EQ(r.status, 2) << c.line;
        EXPECT_EQ(r.err.rfind(std::string("obbsat: ") + c.message, 0), 0u) << r.err;
        EXPECT_EQ(read_file(s.file("v.txt")), "old\n");
        EXPECT_EQ(s.entries(), (std::vector<std::string>{"p.csv", "pairs.csv", "v.txt"}));
    }
    // A bad pair line after good ones: nothing is written to --out either.
    write_file(s.file("p.csv"), "500000.5,1,1,1,1,0\n500001.5,1,1,1,1,0\n");
    write_file(s.file("pairs.csv"), "0,1\n1,0\n0,2\n");
    const run_result r = s.run("collide --poses p.csv --pairs pairs.csv --precision double --out v.txt");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("obbsat: pairs.csv:3: index 2 is out of range", 0), 0u) << r.err;
    EXPECT_EQ(read_file(s.file("v.txt")), "old\n");
}

// `obbsat pairs --precision double` runs once the scene query takes the double
// stores (box_view from pose_records64, rect_records64); until then it is
// refused, before any file is read. Either way this test checks what the
// program does against what the library offers.
TEST(double_precision, pairs_on_doubles_is_the_all_pairs_answer_of_the_double_oracle) {
    const scratch s;
    // Footprints a millimetre apart at 500000.125 and 6e6, in a row: float32
    // rounding closes some of the gaps.
    std::string text;
    std::vector<rect_pose64> poses;
    for (const double base : {500000.125, 6000000.0}) {
        for (int k = 0; k < 6; ++k) {
            poses.push_back(rect_pose64{{base + k * 20.001, base}, {10.0, 5.0}, {1.0, 0.0}});
        }
    }
    for (const rect_pose64& p : poses) {
        text += pose_line(p);
    }
    write_file(s.file("p.csv"), text);
    const run_result r = s.run("pairs --poses p.csv --precision double --out pairs.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string expected;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        for (std::size_t j = i + 1; j < poses.size(); ++j) {
            if (obbsat::oracle::classify(poses[i], poses[j]) != contact::separated) {
                expected += std::to_string(i) + "," + std::to_string(j) + "\n";
            }
        }
    }
    EXPECT_EQ(read_file(s.file("pairs.csv")), expected);
    // --precision float is the default, and accepted when given; the rounding
    // makes some of the millimetre gaps touch, which the double answer keeps apart.
    const run_result f = s.run("pairs --poses p.csv --precision float");
    EXPECT_EQ(f.status, 0) << f.err;
    EXPECT_NE(f.out, "");
    EXPECT_NE(f.out, expected);
}

// ---------------------------------------------------------------------------
// draw --precision double.

// Every number of the points, x, y, x1 ... attributes of an SVG.
std::vector<double> drawn_coordinates(const std::string& svg) {
    static const char* const names[] = {"points", "x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "width", "height"};
    std::vector<double> values;
    for (std::size_t at = svg.find("=\""); at != std::string::npos; at = svg.find("=\"", at + 2)) {
        // The attribute's name: the letters and digits before '='.
        std::size_t begin = at;
        while (begin > 0 && std::isalnum(static_cast<unsigned char>(svg[begin - 1])) != 0) {
            --begin;
        }
        const std::string name = svg.substr(begin, at - begin);
        if (std::find(std::begin(names), std::end(names), name) == std::end(names)) {
            continue;
        }
        const std::size_t end = svg.find('"', at + 2);
        const std::string text = svg.substr(at + 2, end - (at + 2));
        // Its numbers: runs of digits, signs, points and exponents.
        std::size_t k = 0;
        while (k < text.size()) {
            const char c = text[k];
            if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.') {
                std::size_t used = 0;
                values.push_back(std::stod(text.substr(k), &used));
                k += used;
            } else {
                ++k;
            }
        }
    }
    return values;
}

TEST(double_precision, draw_shows_far_pairs_measured_from_their_own_origin) {
    const scratch s;
    // A turned pose at 1e12 and one a double ulp clear of it, touching, and 1 mm in.
    const double far = 1e12;
    const rect_pose64 a{{far, far}, {3.0, 2.0}, {0.6, 0.8}};
    std::vector<rect_pose64> poses;
    for (const double gap : {0.0, 1e-3}) {
        // B's centre along A's x axis at hx_a + hx_b, minus `gap`, rounded to double.
        poses.push_back(a);
        poses.push_back(rect_pose64{{far + (5.0 - gap) * 0.6, far + (5.0 - gap) * 0.8}, {2.0, 1.0}, {0.6, 0.8}});
    }
    poses.push_back(a);
    rect_pose64 clear = poses[1];
    clear.center.x = std::nextafter(std::nextafter(clear.center.x, INFINITY), INFINITY);
    poses.push_back(clear);
    std::string text;
    for (const rect_pose64& p : poses) {
        text += pose_line(p);
    }
    write_file(s.file("p.csv"), text);
    write_file(s.file("pairs.csv"), pair_lines(3));
    const run_result r = s.run("draw --poses p.csv --pairs pairs.csv --select 0-2 --precision double --method exact "
                               "--out far.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = read_file(s.file("far.svg"));
    for (int k = 0; k < 3; ++k) {
        EXPECT_NE(svg.find("id=\"panel-" + std::to_string(k) + "\""), std::string::npos);
    }
    const std::vector<double> coordinates = drawn_coordinates(svg);
    ASSERT_FALSE(coordinates.empty());
    for (const double v : coordinates) {
        EXPECT_TRUE(std::isfinite(v));
        EXPECT_LT(std::fabs(v), 2000.0) << "a coordinate drawn far outside the picture";
    }
    // Each panel's title gives the double oracle's class.
    for (std::size_t k = 0; k < 3; ++k) {
        const contact c = obbsat::oracle::classify(poses[2 * k], poses[2 * k + 1]);
        const char* name = c == contact::separated ? "separated" : c == contact::touching ? "touching" : "overlapping";
        const std::string title = "pair " + std::to_string(k) + ": exact says ";
        const std::size_t at = svg.find(title);
        ASSERT_NE(at, std::string::npos) << title;
        EXPECT_NE(svg.substr(at, 120).find(std::string("exact class: ") + name), std::string::npos)
            << svg.substr(at, 120);
    }
    // The insets measure in double ulps, not float's 65536-metre ones.
    EXPECT_NE(svg.find("double ulps there"), std::string::npos);
    EXPECT_EQ(svg.find("float ulps there"), std::string::npos);

    // Corners: the same pairs, every method on double corners, far out.
    std::string rect_text;
    for (const rect_pose64& p : poses) {
        rect_text += rect_line(corners_of(p));
    }
    write_file(s.file("r.csv"), rect_text);
    for (const char* m : {"exact", "conservative"}) {
        const run_result c = s.run(std::string("draw --rects r.csv --pairs pairs.csv --select 0-2 --precision double "
                                               "--out r.svg --method ") + m);
        ASSERT_EQ(c.status, 0) << c.err;
        for (const double v : drawn_coordinates(read_file(s.file("r.svg")))) {
            EXPECT_LT(std::fabs(v), 2000.0) << m;
        }
    }
    // A method that does not run on doubles is refused, and nothing is written.
    const run_result bad = s.run("draw --poses p.csv --pairs pairs.csv --select 0 --precision double "
                                 "--method sat4 --out bad.svg");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("with --precision double"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(s.file("bad.svg")));
}

}  // namespace
