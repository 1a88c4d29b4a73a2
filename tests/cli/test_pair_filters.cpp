// `obbsat pairs --filters F.csv` (and --against-filters) run as a user runs
// it: the pairs are the unfiltered ones the filter rule lets through and the
// library's own filtered answer; the filter file's format (header, decimal
// and 0x hex, blanks and comments) and its errors, named by file and line,
// with nothing written.
#include "io/csv_input.hpp"
#include "io/filter_input.hpp"
#include "program_runner.hpp"

#include <obbsat/find_pairs.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

std::vector<rect_pose> test_scene(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.seed = seed;
    spec.pairs_per_box = 3.0;
    return obbsat::make_pose_scene(spec);
}

/// The poses as hex floats, so the program reads the very floats of the test.
std::string pose_file(const std::vector<rect_pose>& poses) {
    std::string text = "cx,cy,hx,hy,c,s\n";
    char line[256];
    for (const rect_pose& p : poses) {
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a\n", p.center.x, p.center.y, p.half_extents.x,
                      p.half_extents.y, p.rotation.x, p.rotation.y);
        text += line;
    }
    return text;
}

struct filters {
    std::vector<std::uint64_t> categories, masks;
    std::vector<std::int32_t> groups;

    obbsat::pair_filters view() const { return {categories.data(), masks.data(), groups.data()}; }
};

filters random_filters(std::size_t n, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    filters f;
    for (std::size_t i = 0; i < n; ++i) {
        f.categories.push_back(std::uint64_t{1} << random.below(4));
        f.masks.push_back(random.below(3) == 0 ? 0xfu & ~(std::uint64_t{1} << random.below(4)) : ~std::uint64_t{0});
        f.groups.push_back(random.below(2) == 0 ? 0 : -static_cast<std::int32_t>(i / 3) - 1);
    }
    return f;
}

/// The filter file of `f`, in every form the reader takes: the header,
/// decimal and hex (0x and 0X), blanks around fields, a comment and a blank line.
std::string filter_file(const filters& f) {
    std::string text = "category,mask,group\n# bodies of three\n\n";
    char line[128];
    for (std::size_t i = 0; i < f.groups.size(); ++i) {
        const char* form = i % 3 == 0 ? "%llu,0x%llx,%d\n" : i % 3 == 1 ? "0X%llX , %llu , %d\r\n" : " %llu,%llu,%d\n";
        std::snprintf(line, sizeof line, form, static_cast<unsigned long long>(f.categories[i]),
                      static_cast<unsigned long long>(f.masks[i]), f.groups[i]);
        text += line;
    }
    return text;
}

std::string pair_lines(const std::vector<pair_index>& pairs) {
    std::string text;
    for (const pair_index& p : pairs) {
        text += std::to_string(p.a) + "," + std::to_string(p.b) + "\n";
    }
    return text;
}

bool passes(const filters& x, std::size_t i, const filters& y, std::size_t j) {
    return (x.categories[i] & y.masks[j]) != 0 && (y.categories[j] & x.masks[i]) != 0 &&
           !(x.groups[i] != 0 && x.groups[i] == y.groups[j]);
}

TEST(pair_filters_file, one_file_gives_the_unfiltered_pairs_the_rule_lets_through) {
    const scratch s;
    const auto poses = test_scene(3000, 5);
    const filters f = random_filters(poses.size(), 6);
    write_file(s.file("Q.csv"), pose_file(poses));
    write_file(s.file("F.csv"), filter_file(f));
    obbsat::collide_options exact;
    exact.test = obbsat::method::exact;
    std::vector<pair_index> want;
    const auto all = obbsat::find_pairs(poses, exact);
    for (const pair_index& p : all) {
        if (passes(f, p.a, f, p.b)) {
            want.push_back(p);
        }
    }
    ASSERT_LT(want.size(), all.size());
    ASSERT_EQ(pair_lines(all), s.run("pairs --poses Q.csv").out);
    const run_result r = s.run("pairs --poses Q.csv --filters F.csv --threads 2");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, pair_lines(want));
    EXPECT_EQ(r.out, pair_lines(obbsat::find_pairs(obbsat::box_view(poses).with_filters(f.view()), exact)));
}

TEST(pair_filters_file, each_file_of_a_cross_query_has_its_own) {
    const scratch s;
    const auto all = test_scene(2000, 7);
    const std::vector<rect_pose> a(all.begin(), all.begin() + 1200), b(all.begin() + 1200, all.end());
    const filters fa = random_filters(a.size(), 8), fb = random_filters(b.size(), 9);
    write_file(s.file("A.csv"), pose_file(a));
    write_file(s.file("B.csv"), pose_file(b));
    write_file(s.file("FA.csv"), filter_file(fa));
    write_file(s.file("FB.csv"), filter_file(fb));
    obbsat::collide_options exact;
    exact.test = obbsat::method::exact;
    const auto across = obbsat::find_pairs(a, b, exact);
    std::vector<pair_index> both, only_b;
    const filters none{std::vector<std::uint64_t>(a.size(), ~std::uint64_t{0}),
                       std::vector<std::uint64_t>(a.size(), ~std::uint64_t{0}), std::vector<std::int32_t>(a.size(), 0)};
    for (const pair_index& p : across) {
        if (passes(fa, p.a, fb, p.b)) {
            both.push_back(p);
        }
        if (passes(none, p.a, fb, p.b)) {
            only_b.push_back(p);
        }
    }
    ASSERT_LT(both.size(), only_b.size());
    const run_result r = s.run("pairs --poses A.csv --against-poses B.csv --filters FA.csv --against-filters FB.csv");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, pair_lines(both));
    EXPECT_EQ(s.run("pairs --poses A.csv --against-poses B.csv --against-filters FB.csv").out, pair_lines(only_b));
}

class filter_file_errors : public ::testing::Test {
protected:
    void SetUp() override {
        write_file(s.file("Q.csv"), "0,0,1,1,1,0\n1,0,1,1,1,0\n# c\n2,0,1,1,1,0\n");
        write_file(s.file("old.csv"), "previous pairs\n");
    }

    /// `obbsat pairs ARGS` fails with exit status 2 and "obbsat: MESSAGE", writes nothing, leaves --out as it was.
    void expect_rejected(const std::string& filter_text, const std::string& args, const std::string& message) {
        write_file(s.file("F.csv"), filter_text);
        const run_result r = s.run("pairs --poses Q.csv " + args + " --out old.csv");
        EXPECT_EQ(r.status, 2) << filter_text;
        EXPECT_EQ(r.err, "obbsat: " + message + "\n") << filter_text;
        EXPECT_EQ(r.out, "") << filter_text;
        EXPECT_EQ(read_file(s.file("old.csv")), "previous pairs\n") << filter_text;
    }

    scratch s;
};

TEST_F(filter_file_errors, a_good_file_is_read_first) {
    write_file(s.file("F.csv"), "1,1,0\n1,2,0\n3,3,0\n");
    // Without filters every pair collides (0 and 2 touch). 0-1: category 1 & mask 2 = 0, dropped;
    // 0-2 and 1-2: both ways meet.
    EXPECT_EQ(s.run("pairs --poses Q.csv").out, "0,1\n0,2\n1,2\n");
    const run_result r = s.run("pairs --poses Q.csv --filters F.csv");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "0,2\n1,2\n");
    write_file(s.file("G.csv"), "1,1,-0x7\n1,0xffffffffffffffff,0\n1,1,-7\n");
    EXPECT_EQ(s.run("pairs --poses Q.csv --filters G.csv").out, "0,1\n1,2\n");
}

TEST_F(filter_file_errors, are_named_by_file_and_line) {
    expect_rejected("1,1,0\n1,1,0\n", "--filters F.csv",
                    "F.csv: 2 filter lines for the 3 rectangles of Q.csv: one line per rectangle");
    expect_rejected("1,1,0\n1,1,0\n# c\n1,1,0\n1,1,0\n", "--filters F.csv",
                    "F.csv:5: one filter line more than the 3 rectangles of Q.csv");
    expect_rejected("1,1,0\n-1,1,0\n1,1,0\n", "--filters F.csv",
                    "F.csv:2: field 1 (category): '-1' is negative; category is a set of bits");
    expect_rejected("1,1,0\n1,0x1ffffffffffffffff,0\n1,1,0\n", "--filters F.csv",
                    "F.csv:2: field 2 (mask): '0x1ffffffffffffffff' is out of range");
    expect_rejected("1,1,0\n1,1,2147483648\n1,1,0\n", "--filters F.csv",
                    "F.csv:2: field 3 (group): '2147483648' is out of range (-2147483648 to 2147483647)");
    expect_rejected("1,1,0\n1,1.5,0\n1,1,0\n", "--filters F.csv",
                    "F.csv:2: field 2 (mask): '1.5' is not an integer (decimal, or hexadecimal after 0x)");
    expect_rejected("1,1,0\n1,+1,0\n1,1,0\n", "--filters F.csv",
                    "F.csv:2: field 2 (mask): '+1' is not an integer (decimal, or hexadecimal after 0x)");
    expect_rejected("1,1,0\n1,,0\n1,1,0\n", "--filters F.csv", "F.csv:2: field 2 (mask) is empty");
    expect_rejected("1,1\n", "--filters F.csv", "F.csv:1: expected 3 comma-separated fields (category,mask,group), found 2");
    expect_rejected("category,mask,body\n", "--filters F.csv",
                    "F.csv:1: expected the header 'category,mask,group' or a filter line, found 'category,mask,body'");
    expect_rejected("", "--filters nothere.csv", "nothere.csv: cannot open: No such file or directory");
}

TEST_F(filter_file_errors, usage_errors) {
    const std::string see_help = " (see 'obbsat pairs --help')";
    expect_rejected("1,1,0\n1,1,0\n1,1,0\n", "--filters -",
                    "pairs: --filters reads a file, not standard input ('-')" + see_help);
    expect_rejected("1,1,0\n1,1,0\n1,1,0\n", "--against-filters F.csv",
                    "pairs: --against-filters without --against-rects or --against-poses" + see_help);
}

TEST(filter_reader, reads_every_form_to_the_same_values) {
    const std::string text = "category,mask,group\n0x10,18446744073709551615,-2147483648\n 7 , 0XfF ,0x7fffffff\n";
    obbsat::io::line_reader lines(text, "F.csv");
    const obbsat::io::filter_columns f = obbsat::io::read_filters(lines, 2, "Q.csv");
    EXPECT_EQ(f.categories, (std::vector<std::uint64_t>{16, 7}));
    EXPECT_EQ(f.masks, (std::vector<std::uint64_t>{~std::uint64_t{0}, 255}));
    EXPECT_EQ(f.groups, (std::vector<std::int32_t>{-2147483647 - 1, 2147483647}));
}

}  // namespace
