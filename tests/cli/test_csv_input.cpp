// The CLI's readers: what they accept, and for every rejected line the file,
// line number and reason of the error.
#include "io/csv_input.hpp"
#include "io/status_line.hpp"

#include <obbsat/pose.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_pose.hpp>

#include <gtest/gtest.h>

#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_soa;
using obbsat::io::input_error;
using obbsat::io::line_reader;
using obbsat::io::pair_reader;

const std::string unit_rect = "0,1,1,1,1,0,0,0";

rect_soa rects_of(const std::string& text,
                  std::size_t chunk_bytes = line_reader::default_chunk_bytes) {
    line_reader lines(text, "R.csv", chunk_bytes);
    return obbsat::io::read_rects(lines);
}

std::vector<pair_index> pairs_of(const std::string& text, std::uint64_t rect_count,
                                 std::size_t chunk_bytes = line_reader::default_chunk_bytes) {
    line_reader lines(text, "P.csv", chunk_bytes);
    pair_reader reader(lines, rect_count, "R.csv");
    std::vector<pair_index> all;
    std::vector<pair_index> chunk;
    while (reader.read_chunk(chunk, 1000)) {
        all.insert(all.end(), chunk.begin(), chunk.end());
    }
    return all;
}

input_error rect_error(const std::string& text,
                       std::size_t chunk_bytes = line_reader::default_chunk_bytes) {
    try {
        rects_of(text, chunk_bytes);
    } catch (const input_error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for rectangle text:\n" << text;
    return input_error("", 0, "");
}

input_error pair_error(const std::string& text, std::uint64_t rect_count = 10) {
    try {
        pairs_of(text, rect_count);
    } catch (const input_error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for pair text:\n" << text;
    return input_error("", 0, "");
}

// The eight coordinates of rectangle i, in file order.
std::vector<float> coords(const rect_soa& rects, std::size_t i) {
    const rect r = rects.at(i);
    return {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
}

// A rectangle line whose coordinate `index` is `value` and the others 0.
std::string line_with(std::size_t index, const std::string& value) {
    std::string line;
    for (std::size_t k = 0; k < 8; ++k) {
        line += (k == 0 ? "" : ",") + (k == index ? value : std::string("0"));
    }
    return line;
}

float single_value(const std::string& value) {
    const rect_soa rects = rects_of(line_with(3, value) + "\n");
    EXPECT_EQ(rects.size(), 1u);
    return coords(rects, 0)[3];
}

TEST(csv_input, reads_decimal_rectangles_exactly) {
    const rect_soa rects = rects_of("1.5,-2,0.1,3e2,-0,7,1e-3,12345.678\n" + unit_rect + "\n");
    ASSERT_EQ(rects.size(), 2u);
    const std::vector<float> want = {1.5f, -2.0f, 0.1f, 300.0f, -0.0f, 7.0f, 1e-3f, 12345.678f};
    EXPECT_EQ(coords(rects, 0), want);
    EXPECT_EQ(coords(rects, 1), (std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}));
}

TEST(csv_input, reads_hex_floats_exactly) {
    EXPECT_EQ(single_value("0x1.8p+1"), 3.0f);
    EXPECT_EQ(single_value("-0x1.fffffep+127"), -FLT_MAX);
    EXPECT_EQ(single_value("0x1.000002p+0"), 1.0f + FLT_EPSILON);
    EXPECT_EQ(single_value("0X1P-3"), 0.125f);
}

TEST(csv_input, accepts_subnormals_and_underflow_to_zero) {
    EXPECT_EQ(single_value("0x1p-149"), std::numeric_limits<float>::denorm_min());
    EXPECT_EQ(single_value("1e-40"), 1e-40f);
    EXPECT_GT(single_value("1e-40"), 0.0f);
    EXPECT_LT(single_value("1e-40"), FLT_MIN);
    EXPECT_EQ(single_value("-1.17549421e-38"), -1.17549421e-38f);
    EXPECT_EQ(single_value("1e-50"), 0.0f);
}

TEST(csv_input, accepts_values_that_round_to_the_largest_float) {
    EXPECT_EQ(single_value("3.4028235e38"), FLT_MAX);
    EXPECT_EQ(single_value("-3.40282356e38"), -FLT_MAX);
}

TEST(csv_input, rejects_overflow_with_line_and_field) {
    const input_error e = rect_error(unit_rect + "\n" + line_with(2, "1e39") + "\n");
    EXPECT_EQ(e.file(), "R.csv");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(),
              "field 3 (urx): '1e39' is out of float range (magnitude above 3.40282347e+38)");
    EXPECT_EQ(std::string(e.what()), "R.csv:2: " + e.reason());
    EXPECT_NE(rect_error(line_with(0, "-1e39")).reason().find("out of float range"),
              std::string::npos);
    EXPECT_NE(rect_error(line_with(7, "3.5e38")).reason().find("field 8 (lly)"), std::string::npos);
    EXPECT_NE(rect_error(line_with(7, "0x1p128")).reason().find("out of float range"),
              std::string::npos);
}

TEST(csv_input, rejects_nan_and_infinity) {
    for (const char* value : {"nan", "NaN", "-nan", "nan(0x1)", "inf", "-inf", "INF", "infinity"}) {
        const input_error e = rect_error(line_with(4, value));
        EXPECT_EQ(e.line(), 1u) << value;
        EXPECT_EQ(e.reason(), "field 5 (lrx): '" + std::string(value) + "' is not finite") << value;
    }
}

TEST(csv_input, rejects_garbage_numbers) {
    for (const char* value : {"abc", "1.5x", "0x", "1 2", "--1", "1e", ".", "1,5"}) {
        const input_error e = rect_error("# header\n" + line_with(1, value) + "\n");
        EXPECT_EQ(e.line(), 2u) << value;
        if (std::string(value) == "1,5") {
            EXPECT_EQ(e.reason(), "expected 8 comma-separated fields "
                                  "(ulx,uly,urx,ury,lrx,lry,llx,lly), found 9");
        } else {
            EXPECT_EQ(e.reason(), "field 2 (uly): '" + std::string(value) + "' is not a number")
                << value;
        }
    }
}

TEST(csv_input, rejects_empty_fields) {
    const input_error e = rect_error("0,1,1,,1,0,0,0\n");
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.reason(), "field 4 (ury) is empty");
    EXPECT_EQ(rect_error("0,1,1,1,1,0,0,  \n").reason(), "field 8 (lly) is empty");
}

TEST(csv_input, rejects_wrong_field_counts) {
    EXPECT_EQ(rect_error("0,1,1,1,1,0,0\n").reason(),
              "expected 8 comma-separated fields (ulx,uly,urx,ury,lrx,lry,llx,lly), found 7");
    EXPECT_EQ(rect_error(unit_rect + ",0\n").reason(),
              "expected 8 comma-separated fields (ulx,uly,urx,ury,lrx,lry,llx,lly), found 9");
    EXPECT_EQ(pair_error("1,2\n1\n").reason(), "expected 2 comma-separated fields (i,j), found 1");
    EXPECT_EQ(pair_error("1,2\n1\n").line(), 2u);
    EXPECT_EQ(pair_error("1,2,3\n").reason(), "expected 2 comma-separated fields (i,j), found 3");
}

TEST(csv_input, accepts_crlf_and_blanks_around_fields) {
    const rect_soa rects = rects_of(" 0 ,\t1, 1 ,1,1,0,0,0 \r\n" + unit_rect + "\r\n");
    ASSERT_EQ(rects.size(), 2u);
    EXPECT_EQ(coords(rects, 0), coords(rects, 1));
    const auto pairs = pairs_of("0,1\r\n 2 , 3 \r\n", 4);
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[1].a, 2u);
    EXPECT_EQ(pairs[1].b, 3u);
}

TEST(csv_input, reads_a_last_line_without_line_end) {
    EXPECT_EQ(rects_of(unit_rect + "\n" + unit_rect).size(), 2u);
    EXPECT_EQ(rects_of(unit_rect + "\r\n" + unit_rect + "\r").size(), 2u);
    const auto pairs = pairs_of("0,1\n1,0", 2);
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[1].a, 1u);
}

TEST(csv_input, ignores_a_byte_order_mark_only_at_the_start) {
    const std::string bom = "\xef\xbb\xbf";
    EXPECT_EQ(rects_of(bom + unit_rect + "\n").size(), 1u);
    EXPECT_EQ(rects_of(bom + "# comment\n" + unit_rect).size(), 1u);
    EXPECT_EQ(pairs_of(bom + "0,0\n", 1).size(), 1u);
    const input_error e = rect_error(unit_rect + "\n" + bom + unit_rect + "\n");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(), "field 1 (ulx): '\\xef\\xbb\\xbf0' is not a number");
}

TEST(csv_input, skips_comments_and_blank_lines_but_counts_them) {
    const std::string text = "# ulx,uly,...\n\n   \n\t# indented comment\r\n" + unit_rect +
                             "\n#" + unit_rect + "\n" + line_with(0, "x") + "\n";
    const input_error e = rect_error(text);
    EXPECT_EQ(e.line(), 7u);
    EXPECT_EQ(rects_of("#only comments\n\n").size(), 0u);
    EXPECT_EQ(rects_of("").size(), 0u);
    EXPECT_EQ(pairs_of("# i,j\n\n0,0\n  # x\n", 1).size(), 1u);
}

TEST(csv_input, rejects_a_carriage_return_inside_a_line) {
    const input_error e = rect_error("0,1,1\r,1,1,0,0,0\n");
    EXPECT_EQ(e.reason(), "field 3 (urx): '1\\x0d' is not a number");
}

TEST(csv_input, escapes_and_shortens_garbage_in_messages) {
    const input_error nul = rect_error(line_with(0, std::string("1\0", 2)));
    EXPECT_EQ(nul.reason(), "field 1 (ulx): '1\\x00' is not a number");
    const input_error long_field = rect_error(line_with(0, std::string(100, 'z')));
    EXPECT_EQ(long_field.reason(),
              "field 1 (ulx): '" + std::string(40, 'z') + "...' is not a number");
}

TEST(csv_input, reads_long_fields_and_lines) {
    // A 300-digit field, longer than any stack buffer, still reads exactly.
    const std::string long_number = "1." + std::string(298, '0');
    EXPECT_EQ(single_value(long_number), 1.0f);
    // A line much longer than a read chunk.
    std::string padded;
    for (std::size_t k = 0; k < 8; ++k) {
        padded += (k == 0 ? "" : ",") + std::string(5000, ' ') + "0.5" + std::string(5000, '\t');
    }
    const rect_soa rects = rects_of(padded + "\n" + unit_rect + "\n", 64);
    ASSERT_EQ(rects.size(), 2u);
    EXPECT_EQ(coords(rects, 0), std::vector<float>(8, 0.5f));
}

TEST(csv_input, rejects_a_line_longer_than_the_limit) {
    const std::string text = unit_rect + "\n" + std::string(5000, ' ') + unit_rect + "\n";
    line_reader lines(text, "R.csv", 64, 1024);
    try {
        obbsat::io::read_rects(lines);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(e.line(), 2u);
        EXPECT_EQ(e.reason(), "line is longer than 1024 bytes");
    }
}

TEST(csv_input, results_do_not_depend_on_chunk_boundaries) {
    std::string rect_text = "# comment\r\n";
    std::string pair_text = "# pairs\n";
    for (int i = 0; i < 40; ++i) {
        rect_text += std::to_string(i) + ".25, 0x1.8p" + std::to_string(i % 5) + ",1,1,1,0,0,0" +
                     (i % 3 == 0 ? "\r\n" : "\n") + (i % 7 == 0 ? "\n" : "");
        pair_text += std::to_string(i) + "," + std::to_string(39 - i) + (i % 2 ? "\r\n" : "\n");
    }
    const rect_soa want_rects = rects_of(rect_text);
    const std::vector<pair_index> want_pairs = pairs_of(pair_text, 40);
    ASSERT_EQ(want_rects.size(), 40u);
    ASSERT_EQ(want_pairs.size(), 40u);
    const std::string bad_text = rect_text + unit_rect + "\n" + line_with(6, "1e40");
    const input_error want_error = rect_error(bad_text);
    for (std::size_t chunk = 1; chunk <= 70; ++chunk) {
        const rect_soa got_rects = rects_of(rect_text, chunk);
        ASSERT_EQ(got_rects.size(), want_rects.size()) << "chunk " << chunk;
        for (std::size_t i = 0; i < want_rects.size(); ++i) {
            ASSERT_EQ(coords(got_rects, i), coords(want_rects, i)) << "chunk " << chunk;
        }
        const std::vector<pair_index> got_pairs = pairs_of(pair_text, 40, chunk);
        ASSERT_EQ(got_pairs.size(), want_pairs.size()) << "chunk " << chunk;
        for (std::size_t i = 0; i < want_pairs.size(); ++i) {
            ASSERT_EQ(got_pairs[i].a, want_pairs[i].a);
            ASSERT_EQ(got_pairs[i].b, want_pairs[i].b);
        }
        const input_error got_error = rect_error(bad_text, chunk);
        EXPECT_EQ(got_error.line(), want_error.line()) << "chunk " << chunk;
        EXPECT_EQ(got_error.reason(), want_error.reason()) << "chunk " << chunk;
    }
}

TEST(csv_input, reads_indices_up_to_the_32_bit_limit) {
    const std::uint64_t every_index = std::uint64_t{1} << 32;
    const auto pairs = pairs_of("4294967295,0\n007,4294967294\n", every_index);
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[0].a, 4294967295u);
    EXPECT_EQ(pairs[1].a, 7u);
    EXPECT_EQ(pairs[1].b, 4294967294u);
}

TEST(csv_input, rejects_indices_beyond_32_bits) {
    const std::uint64_t every_index = std::uint64_t{1} << 32;
    const input_error e = pair_error("0,1\n4294967296,0\n", every_index);
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(),
              "field 1 (i): '4294967296' is too large for a 32-bit index (largest 4294967295)");
    EXPECT_EQ(pair_error("0,99999999999999999999999\n", every_index).reason(),
              "field 2 (j): '99999999999999999999999' is too large for a 32-bit index "
              "(largest 4294967295)");
}

TEST(csv_input, rejects_negative_indices) {
    const input_error e = pair_error("# i,j\n0,-1\n");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(), "field 2 (j): '-1' is negative; indices are 0-based and unsigned");
}

TEST(csv_input, rejects_indices_that_are_not_decimal_integers) {
    for (const char* index : {"1.5", "+1", "0x10", "1e3", "a", "1 1", "٣"}) {
        const input_error e = pair_error(std::string(index) + ",0\n");
        EXPECT_EQ(e.line(), 1u) << index;
        EXPECT_NE(e.reason().find("is not an unsigned decimal integer"), std::string::npos)
            << e.reason();
    }
    EXPECT_EQ(pair_error("0,\n").reason(), "field 2 (j) is empty");
}

TEST(csv_input, rejects_indices_out_of_range_of_the_rectangle_file) {
    const input_error e = pair_error("0,4\n4,5\n", 5);
    EXPECT_EQ(e.file(), "P.csv");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(), "index 5 is out of range: R.csv holds 5 rectangles (indices 0 to 4)");
    EXPECT_EQ(pair_error("7,0\n", 5).reason(),
              "index 7 is out of range: R.csv holds 5 rectangles (indices 0 to 4)");
}

TEST(csv_input, rejects_any_index_into_an_empty_rectangle_file) {
    const input_error e = pair_error("\n0,0\n", 0);
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(), "index 0 refers to a rectangle, but R.csv holds none");
    EXPECT_TRUE(pairs_of("# no pairs\n", 0).empty());
}

TEST(csv_input, reads_pairs_in_bounded_chunks) {
    std::string text;
    for (int i = 0; i < 10; ++i) {
        text += std::to_string(i) + "," + std::to_string(i) + "\n";
    }
    text += "10,x\n";
    line_reader lines(text, "P.csv");
    pair_reader reader(lines, 100, "R.csv");
    std::vector<pair_index> chunk;
    for (int part = 0; part < 3; ++part) {
        ASSERT_TRUE(reader.read_chunk(chunk, 3));
        ASSERT_EQ(chunk.size(), 3u);
        EXPECT_EQ(chunk[0].a, static_cast<std::uint32_t>(3 * part));
    }
    // The bad line comes after one good pair of the last chunk.
    try {
        reader.read_chunk(chunk, 3);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(e.line(), 11u);
    }
    EXPECT_EQ(reader.pairs_read(), 9u);
}

TEST(csv_input, limits_the_number_of_rectangles) {
    const std::string text = unit_rect + "\n# c\n" + unit_rect + "\n" + unit_rect + "\n" + unit_rect;
    line_reader lines(text, "R.csv");
    try {
        obbsat::io::read_rects(lines, 3);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(e.line(), 5u);
        EXPECT_EQ(e.reason(), "more than 3 rectangles; pairs index rectangles with 32-bit indices");
    }
}

TEST(csv_input, both_stores_read_the_same_rectangles) {
    const std::string text = "# c\n0x1p-149,2,3,4,5,6,7,8\r\n\n-1,-2.5,1e30,-4,5,6,7,8";
    line_reader soa_lines(text, "R.csv", 5);
    const rect_soa soa = obbsat::io::read_rects(soa_lines);
    line_reader record_lines(text, "R.csv", 5);
    const obbsat::rect_records records = obbsat::io::read_rect_records(record_lines);
    ASSERT_EQ(soa.size(), 2u);
    ASSERT_EQ(records.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const rect r = records[i];
        EXPECT_EQ(coords(soa, i), (std::vector<float>{r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x,
                                                      r.lr.y, r.ll.x, r.ll.y}));
    }
    const std::string bad_text = text + "\n1,2,3,4,5,6,7,inf\n";
    line_reader bad_lines(bad_text, "R.csv");
    try {
        obbsat::io::read_rect_records(bad_lines);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(std::string(e.what()), "R.csv:5: field 8 (lly): 'inf' is not finite");
    }
    line_reader many_lines(text, "R.csv");
    EXPECT_THROW(obbsat::io::read_rect_records(many_lines, 1), input_error);
}

TEST(csv_input, reads_files_and_names_missing_ones) {
    char path[] = "/tmp/obbsat_csv_input_XXXXXX";
    const int fd = mkstemp(path);
    ASSERT_GE(fd, 0);
    std::FILE* f = fdopen(fd, "w");
    ASSERT_NE(f, nullptr);
    std::fputs("0x1p0,2,3,4,5,6,7,8\r\n-1,-2,-3,-4,-5,-6,-7,-8", f);
    std::fclose(f);
    const rect_soa rects = obbsat::io::read_rects_file(path);
    std::remove(path);
    ASSERT_EQ(rects.size(), 2u);
    EXPECT_EQ(coords(rects, 1), (std::vector<float>{-1, -2, -3, -4, -5, -6, -7, -8}));
    try {
        obbsat::io::read_rects_file(path);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(e.line(), 0u);
        EXPECT_EQ(std::string(e.what()), std::string(path) + ": cannot open: No such file or directory");
    }
}

// ---------------------------------------------------------------------------
// Pose files: cx,cy,hx,hy,c,s or cx,cy,hx,hy,angle per line.

using obbsat::point;
using obbsat::pose_records;
using obbsat::rect_pose;

pose_records poses_of(const std::string& text,
                      std::size_t chunk_bytes = line_reader::default_chunk_bytes) {
    line_reader lines(text, "Q.csv", chunk_bytes);
    return obbsat::io::read_pose_records(lines);
}

input_error pose_error(const std::string& text,
                       std::size_t chunk_bytes = line_reader::default_chunk_bytes) {
    try {
        poses_of(text, chunk_bytes);
    } catch (const input_error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for pose text:\n" << text;
    return input_error("", 0, "");
}

// The six floats of a pose, in file order.
std::vector<float> pose_values(const rect_pose& p) {
    return {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x, p.rotation.y};
}

bool same_bits(const rect_pose& x, const rect_pose& y) {
    const std::vector<float> a = pose_values(x);
    const std::vector<float> b = pose_values(y);
    return std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(csv_input_poses, reads_rotation_vectors_exactly) {
    const pose_records poses =
        poses_of("1.5,-2,0.1,3e2,0.6,0.8\n0x1.8p+1, -0x1p-149 ,0X1P-3,0,-1,0\n1e-50,0,0,1,0,-0x1.000002p+0\n");
    ASSERT_EQ(poses.size(), 3u);
    EXPECT_EQ(pose_values(poses[0]), (std::vector<float>{1.5f, -2.0f, 0.1f, 300.0f, 0.6f, 0.8f}));
    EXPECT_EQ(pose_values(poses[1]), (std::vector<float>{3.0f, -std::numeric_limits<float>::denorm_min(),
                                                         0.125f, 0.0f, -1.0f, 0.0f}));
    EXPECT_EQ(pose_values(poses[2]), (std::vector<float>{0.0f, 0.0f, 0.0f, 1.0f, 0.0f, -(1.0f + FLT_EPSILON)}));
}

TEST(csv_input_poses, reads_angles_through_rect_pose_of) {
    const pose_records poses = poses_of("# cx,cy,hx,hy,angle\n0,0,2,1,0.3\n-7.5,0x1p20,0.5,4,-0x1.921fb6p+1\n");
    ASSERT_EQ(poses.size(), 2u);
    const obbsat::pose first{{0, 0}, {2, 1}, 0.3f};
    const obbsat::pose second{{-7.5f, 1048576.0f}, {0.5f, 4.0f}, -3.14159274f};
    EXPECT_TRUE(same_bits(poses[0], obbsat::rect_pose_of(first)));
    EXPECT_TRUE(same_bits(poses[1], obbsat::rect_pose_of(second)));
    EXPECT_EQ(poses[0].rotation.x, static_cast<float>(std::cos(static_cast<double>(0.3f))));
    EXPECT_EQ(poses[0].rotation.y, static_cast<float>(std::sin(static_cast<double>(0.3f))));
}

TEST(csv_input_poses, mixes_angle_and_rotation_lines_in_one_file) {
    const pose_records poses = poses_of("0,0,1,1,0\r\n\n0,0,1,1,1,0\n  # c\n0,0,1,1,0,1\n0,0,1,1,1.5");
    ASSERT_EQ(poses.size(), 4u);
    EXPECT_TRUE(same_bits(poses[0], poses[1]));
    EXPECT_EQ(poses[2].rotation.x, 0.0f);
    EXPECT_EQ(poses[3].rotation.x, static_cast<float>(std::cos(1.5)));
}

TEST(csv_input_poses, accepts_zero_half_extents_negative_zero_included) {
    const pose_records poses = poses_of("0,0,0,0,1,0\n0,0,-0,-0x0p+0,1,0\n0,0,-1e-50,1,1,0\n");
    ASSERT_EQ(poses.size(), 3u);
    EXPECT_EQ(poses[1].half_extents.x, 0.0f);
    EXPECT_EQ(poses[2].half_extents.x, 0.0f);
}

TEST(csv_input_poses, rejects_negative_half_extents_naming_the_field) {
    const input_error e = pose_error("0,0,1,1,1,0\n# c\n0,0,1,-1,1,0\n");
    EXPECT_EQ(e.file(), "Q.csv");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.reason(), "field 4 (hy): '-1' is negative (a half extent must be >= 0)");
    EXPECT_EQ(std::string(e.what()), "Q.csv:3: " + e.reason());
    EXPECT_EQ(pose_error("0,0,-0x1p-149,1,1,0\n").reason(),
              "field 3 (hx): '-0x1p-149' is negative (a half extent must be >= 0)");
    EXPECT_EQ(pose_error("0,0,-2,1,0.5\n").reason(),
              "field 3 (hx): '-2' is negative (a half extent must be >= 0)");
    // Fields are checked in order: a bad number after a negative half extent is not reached.
    EXPECT_EQ(pose_error("0,0,-2,x,1,0\n").reason(),
              "field 3 (hx): '-2' is negative (a half extent must be >= 0)");
}

TEST(csv_input_poses, rejects_a_zero_rotation_vector) {
    const input_error e = pose_error("0,0,1,1,1,0\n0,0,1,1,0,-0\n");
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.reason(), "fields 5 and 6 (c, s): '0', '-0' make the rotation vector (0, 0), which has no "
                          "direction");
    // Values that round to zero are zero.
    EXPECT_EQ(pose_error("0,0,1,1,1e-50,0x0.0p0\n").reason(),
              "fields 5 and 6 (c, s): '1e-50', '0x0.0p0' make the rotation vector (0, 0), which has no "
              "direction");
}

TEST(csv_input_poses, rejects_non_finite_and_overflowing_values) {
    EXPECT_EQ(pose_error("nan,0,1,1,1,0\n").reason(), "field 1 (cx): 'nan' is not finite");
    EXPECT_EQ(pose_error("0,0,1,1,1,-inf\n").reason(), "field 6 (s): '-inf' is not finite");
    EXPECT_EQ(pose_error("0,0,1,1,inf\n").reason(), "field 5 (angle): 'inf' is not finite");
    EXPECT_EQ(pose_error("0,0,1,1,1,0\n0,0,1e39,1,1,0\n").reason(),
              "field 3 (hx): '1e39' is out of float range (magnitude above 3.40282347e+38)");
    EXPECT_EQ(pose_error("0,0,1,1,1,0\n0,0,1e39,1,1,0\n").line(), 2u);
    EXPECT_EQ(pose_error("0,0,1,1,0x1p128\n").reason(),
              "field 5 (angle): '0x1p128' is out of float range (magnitude above 3.40282347e+38)");
}

TEST(csv_input_poses, rejects_garbage_and_empty_fields) {
    EXPECT_EQ(pose_error("0,0,1,1,1,0x\n").reason(), "field 6 (s): '0x' is not a number");
    EXPECT_EQ(pose_error("0,0,1,1,1,0 trailing\n").reason(), "field 6 (s): '0 trailing' is not a number");
    EXPECT_EQ(pose_error("0,0,1,1,0.5rad\n").reason(), "field 5 (angle): '0.5rad' is not a number");
    EXPECT_EQ(pose_error("0,,1,1,1,0\n").reason(), "field 2 (cy) is empty");
    EXPECT_EQ(pose_error("0,0,1,1,\n").reason(), "field 5 (angle) is empty");
    EXPECT_EQ(pose_error("0,0,1,1,1,\n").reason(), "field 6 (s) is empty");
}

TEST(csv_input_poses, rejects_wrong_field_counts) {
    const std::string layout = "(cx,cy,hx,hy,angle or cx,cy,hx,hy,c,s)";
    EXPECT_EQ(pose_error("0,0,1,1\n").reason(), "expected 5 or 6 comma-separated fields " + layout + ", found 4");
    EXPECT_EQ(pose_error("0,0,1,1,1,0,0\n").reason(),
              "expected 5 or 6 comma-separated fields " + layout + ", found 7");
    EXPECT_EQ(pose_error("0,0,1,1,1,0\n" + unit_rect + "\n").reason(),
              "expected 5 or 6 comma-separated fields " + layout + ", found 8");
    EXPECT_EQ(pose_error("0,0,1,1,1,0\n" + unit_rect + "\n").line(), 2u);
    EXPECT_EQ(pose_error("0,0,1,1,1,0\nx\n").reason(), "expected 5 or 6 comma-separated fields " + layout + ", found 1");
    // On line 1, a line of names only is a header, and this one is wrong.
    EXPECT_EQ(pose_error("x\n").reason(),
              "expected the header 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' or a pose, found 'x'");
}

TEST(csv_input_poses, skips_what_the_rectangle_reader_skips) {
    const std::string bom = "\xef\xbb\xbf";
    EXPECT_EQ(poses_of(bom + "# header\n\n \t\n0,0,1,1,1,0\r\n0,0,1,1,0").size(), 2u);
    EXPECT_EQ(poses_of("").size(), 0u);
    EXPECT_EQ(poses_of("# only a comment").size(), 0u);
}

TEST(csv_input_poses, limits_the_number_of_poses) {
    const std::string text = "0,0,1,1,1,0\n# c\n0,0,1,1,0\n0,0,1,1,0\n";
    line_reader lines(text, "Q.csv");
    try {
        obbsat::io::read_pose_records(lines, 2);
        FAIL() << "no error";
    } catch (const input_error& e) {
        EXPECT_EQ(e.line(), 4u);
        EXPECT_EQ(e.reason(), "more than 2 poses; pairs index poses with 32-bit indices");
    }
}

TEST(csv_input_poses, results_do_not_depend_on_chunk_boundaries) {
    std::string text = "# poses\r\n";
    for (int i = 0; i < 40; ++i) {
        text += std::to_string(i) + ".25, 0x1.8p" + std::to_string(i % 5) + ",1,2" +
                (i % 2 == 0 ? ",0.6,-0.8" : ", 0.1") + (i % 3 == 0 ? "\r\n" : "\n") + (i % 7 == 0 ? "\n" : "");
    }
    const pose_records want = poses_of(text);
    ASSERT_EQ(want.size(), 40u);
    const std::string bad_text = text + "0,0,1,1,1,0\n0,0,1,-3,0.5\n";
    const input_error want_error = pose_error(bad_text);
    EXPECT_EQ(want_error.line(), 49u);
    for (std::size_t chunk = 1; chunk <= 70; ++chunk) {
        const pose_records got = poses_of(text, chunk);
        ASSERT_EQ(got.size(), want.size()) << "chunk " << chunk;
        for (std::size_t i = 0; i < want.size(); ++i) {
            ASSERT_TRUE(same_bits(got[i], want[i])) << "chunk " << chunk << ", pose " << i;
        }
        const input_error got_error = pose_error(bad_text, chunk);
        EXPECT_EQ(got_error.line(), want_error.line()) << "chunk " << chunk;
        EXPECT_EQ(got_error.reason(), want_error.reason()) << "chunk " << chunk;
    }
}

}  // namespace

// ---------------------------------------------------------------------------
// Header lines.

namespace {

obbsat::pose_records poses_named(const std::string& text) {
    line_reader lines(text, "Q.csv");
    return obbsat::io::read_pose_records(lines);
}

input_error pose_named_error(const std::string& text) {
    try {
        poses_named(text);
    } catch (const input_error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for pose text:\n" << text;
    return input_error("", 0, "");
}

}  // namespace

TEST(csv_headers, the_documented_header_on_line_1_is_skipped) {
    EXPECT_EQ(rects_of("ulx,uly,urx,ury,lrx,lry,llx,lly\n" + unit_rect + "\n").size(), 1u);
    EXPECT_EQ(rects_of("\xef\xbb\xbfulx,uly,urx,ury,lrx,lry,llx,lly\r\n" + unit_rect + "\r\n").size(), 1u);
    EXPECT_EQ(rects_of("ulx,uly,urx,ury,lrx,lry,llx,lly").size(), 0u);
    EXPECT_EQ(poses_named("cx,cy,hx,hy,c,s\n0,0,1,1,1,0\n0,0,1,1,0.5\n").size(), 2u);
    EXPECT_EQ(poses_named("cx,cy,hx,hy,angle\n0,0,1,1,0.5\n").size(), 1u);
    const std::vector<pair_index> pairs = pairs_of("i,j\n0,1\n2,3\n", 5);
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[1].a, 2u);
    EXPECT_EQ(pairs[1].b, 3u);
    // Line numbers still count the header.
    EXPECT_EQ(pair_error("i,j\n0,1\n0,x\n").line(), 3u);
    EXPECT_EQ(rect_error("ulx,uly,urx,ury,lrx,lry,llx,lly\n1,2\n").line(), 2u);
}

TEST(csv_headers, a_header_that_is_not_the_documented_one_is_an_error_on_line_1) {
    const input_error e = rect_error("x1,y1,x2,y2,x3,y3,x4,y4\n" + unit_rect + "\n");
    EXPECT_EQ(e.file(), "R.csv");
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.reason(),
              "expected the header 'ulx,uly,urx,ury,lrx,lry,llx,lly' or a rectangle, found 'x1,y1,x2,y2,x3,y3,x4,y4'");
    EXPECT_EQ(std::string(e.what()), "R.csv:1: " + e.reason());
    // Exactly the names: no blanks, no other case, no other order, no quotes.
    for (const char* header : {"cx, cy, hx, hy, c, s", "CX,CY,HX,HY,C,S", "cy,cx,hx,hy,c,s", "\"cx\",cy,hx,hy,c,s",
                               "cx,cy,hx,hy,c,s,extra", "cx,cy,hx,hy", "x"}) {
        const input_error p = pose_named_error(std::string(header) + "\n0,0,1,1,1,0\n");
        EXPECT_EQ(p.line(), 1u) << header;
        EXPECT_EQ(p.reason().rfind("expected the header 'cx,cy,hx,hy,c,s' or 'cx,cy,hx,hy,angle' or a pose", 0), 0u)
            << header << ": " << p.reason();
    }
    EXPECT_EQ(pair_error("a,b\n0,1\n").reason(), "expected the header 'i,j' or a pair, found 'a,b'");
    EXPECT_EQ(pair_error("i,j,k\n").reason(), "expected the header 'i,j' or a pair, found 'i,j,k'");
}

TEST(csv_headers, a_line_1_with_a_number_in_it_keeps_its_number_errors) {
    // nan, inf and friends are numbers strtof reads, not names.
    EXPECT_EQ(rect_error(line_with(7, "nan") + "\n").reason(), "field 8 (lly): 'nan' is not finite");
    EXPECT_EQ(rect_error("inf,nan,infinity,nan(1),INF,NaN,-inf,x\n").reason(), "field 1 (ulx): 'inf' is not finite");
    EXPECT_EQ(pair_error("a,0\n").reason(), "field 1 (i): 'a' is not an unsigned decimal integer");
    // A header after line 1 is a line like any other.
    EXPECT_EQ(pair_error("# c\ni,j\n").reason(), "field 1 (i): 'i' is not an unsigned decimal integer");
    EXPECT_EQ(pair_error("0,1\ni,j\n").line(), 2u);
}

// ---------------------------------------------------------------------------
// Numbers: the from_chars path accepts, refuses and rounds as strtof.

namespace {

// What an error says after the quoted field ("is not a number"), or all of
// it: the quoting of the field is the reader's own.
std::string error_kind(const std::string& reason) {
    const std::size_t quote = reason.rfind("' ");
    return quote == std::string::npos ? reason : reason.substr(quote + 2);
}

// The reader's verdict on one field: the float's bits, or the error.
std::string reader_verdict(const std::string& field) {
    try {
        const rect_soa rects = rects_of(line_with(3, field) + "\n");
        const float v = coords(rects, 0)[3];
        std::uint32_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        return "bits " + std::to_string(bits);
    } catch (const input_error& e) {
        return "error " + error_kind(e.reason());
    }
}

// The same verdict by the rule the reader had before from_chars, in strtof's
// own words: the whole field read, a finite value, an overflow refused.
std::string strtof_verdict(const std::string& field) {
    const std::string label = "field 4 (ury)";
    std::string trimmed = field;
    while (!trimmed.empty() && (trimmed.front() == ' ' || trimmed.front() == '\t')) {
        trimmed.erase(0, 1);
    }
    while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\t')) {
        trimmed.pop_back();
    }
    if (trimmed.empty()) {
        return "error " + label + " is empty";
    }
    const auto error = [](const std::string& kind) { return "error " + kind; };
    char* stop = nullptr;
    errno = 0;
    const float v = std::strtof(trimmed.c_str(), &stop);
    const int e = errno;
    if (stop != trimmed.c_str() + trimmed.size()) {
        return error("is not a number");
    }
    if (std::isinf(v) && e == ERANGE) {
        return error("is out of float range (magnitude above 3.40282347e+38)");
    }
    if (!std::isfinite(v)) {
        return error("is not finite");
    }
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return "bits " + std::to_string(bits);
}

}  // namespace

TEST(csv_numbers, every_form_is_accepted_refused_and_rounded_as_strtof_does) {
    const std::vector<std::string> forms = {
        "0", "-0", "1", "-1", "+1", "+0x1p0", "1.", ".5", "-.5", "1e5", "1E5", "1e+5", "1e-5", "1e", "1e+", "e5",
        "1.5e-45", "1e-46", "-1e-50", "7e-46", "3.4028235e38", "3.4028236e38", "3.40282357e38", "1e39", "-1e39",
        "340282356779733661637539395458142568448", "0.1", "0.30000001192092896", "16777217", "16777219",
        "1.00000005960464477539062500000001", "1.000000059604644775390625",
        "0x1p0", "0X1P0", "-0x1.8p+1", "0x1.8", "0x.8p1", "0x1.fffffep+127", "0x1.ffffffp+127", "0x1p128",
        "0x1p-149", "0x1p-150", "0x1.8p-150", "0x1.000001p0", "0x1.0000011p0", "0x1.000003p0", "0xABCp-4",
        "0x", "0x-1p0", "-0x-1p0", "0x+1p0", "-0x", "0xp1", "0x1p", "0x1p+", "1.8p+1", "a.8p+1", "0x1.8q",
        "inf", "-inf", "INF", "infinity", "-Infinity", "nan", "-nan", "NaN", "nan(0x1)", "nan(", "0xinf",
        "1 5", " 1", "1 ", "\t-2\t", "\v1", "1\v", "1\r", "٣", "0.5f", "1_000", "00001", "-00.5e-0002",
        "1e2147483648", "1e-2147483649", "0x1p2147483648", "0x1p-2147483649",
        std::string(200, '1'), "0." + std::string(60, '0') + "1", "1" + std::string(120, '0') + "e-120"};
    for (const std::string& f : forms) {
        EXPECT_EQ(reader_verdict(f), strtof_verdict(f)) << "'" << f << "'";
    }
}

// Under AddressSanitizer each read costs some 50 times more: the sanitizer
// suite reads a tenth of the floats, the release suite all of them.
#if defined(__SANITIZE_ADDRESS__)
constexpr int random_float_count = 2000;
#else
constexpr int random_float_count = 20000;
#endif

TEST(csv_numbers, random_floats_in_every_written_form_read_back_as_strtof_reads_them) {
    std::mt19937 random(12345);
    for (int k = 0; k < random_float_count; ++k) {
        const std::uint32_t bits = static_cast<std::uint32_t>(random());
        float v = 0;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) {
            continue;
        }
        char text[64];
        std::vector<std::string> written;
        written.emplace_back(text, std::to_chars(text, text + sizeof text, v).ptr);
        std::snprintf(text, sizeof text, "%a", static_cast<double>(v));
        written.emplace_back(text);
        std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
        written.emplace_back(text);
        std::snprintf(text, sizeof text, "%.6e", static_cast<double>(v));  // rounds: not every float
        written.emplace_back(text);
        std::snprintf(text, sizeof text, "%A", static_cast<double>(v));
        written.emplace_back(text);
        for (const std::string& w : written) {
            ASSERT_EQ(reader_verdict(w), strtof_verdict(w)) << "'" << w << "'";
        }
        // Shortest decimal and hex give back the float itself.
        ASSERT_EQ(reader_verdict(written[0]), "bits " + std::to_string(bits)) << written[0];
        ASSERT_EQ(reader_verdict(written[1]), "bits " + std::to_string(bits)) << written[1];
    }
}

// ---------------------------------------------------------------------------
// The status line.

namespace {

std::string written_to(std::FILE* f) {
    std::fflush(f);
    std::rewind(f);
    std::string text;
    for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) {
        text += static_cast<char>(c);
    }
    return text;
}

}  // namespace

TEST(status_line, writes_nothing_off_a_terminal) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        obbsat::io::status_line status(f, false, "obbsat pairs", 0.0);
        EXPECT_FALSE(status.due());
        status.show("reading");
        status.finish("3 poses, 1 pairs");
    }
    EXPECT_EQ(written_to(f), "");
    std::fclose(f);
}

TEST(status_line, on_a_terminal_overwrites_itself_and_ends_with_the_summary) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        obbsat::io::status_line status(f, true, "obbsat pairs", 0.0);
        ASSERT_TRUE(status.due());
        status.show("reading Q.csv: 65536 poses");
        status.show("too soon after the last");  // within a tenth of a second: not shown
        status.finish("1000000 poses, 1996130 pairs");
        EXPECT_FALSE(status.due());
    }
    const std::string text = written_to(f);
    const std::string start = "\r\x1b[Kobbsat pairs: reading Q.csv: 65536 poses\r\x1b[Kobbsat pairs: 1000000 poses, "
                              "1996130 pairs, ";
    EXPECT_EQ(text.rfind(start, 0), 0u) << text;
    EXPECT_EQ(text.find("too soon"), std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 3), " s\n") << text;
    std::fclose(f);
}

TEST(status_line, waits_for_its_delay_and_is_erased_when_the_run_ends_in_an_error) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        obbsat::io::status_line slow(f, true, "obbsat collide", 60.0);
        EXPECT_FALSE(slow.due());
        slow.show("not yet");
        slow.finish("2 poses, 1 pairs");  // the summary needs no delay
    }
    EXPECT_EQ(written_to(f).rfind("obbsat collide: 2 poses, 1 pairs, ", 0), 0u) << written_to(f);
    std::fclose(f);

    f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
        obbsat::io::status_line failing(f, true, "obbsat pairs", 0.0);
        failing.show("reading");
    }  // no finish: an error left the run
    EXPECT_EQ(written_to(f), "\r\x1b[Kobbsat pairs: reading\r\x1b[K");
    std::fclose(f);
}
