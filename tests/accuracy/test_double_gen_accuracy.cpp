// gen and accuracy at --precision double, run as a user runs them: gen's files
// hold the double families' pairs (the makes of obbsat/suites/double_cases.hpp
// through tools/accuracy/double_families) in shortest round-trip decimal or
// hex, with the double oracle's truth, and collide --precision double reads
// them back to the same doubles and answers them exactly; accuracy's JSON holds
// the counts the double references give on the same families, and for float32
// exact on the pairs rounded to float32 the counts of the float oracle on them.
#include "accuracy/double_families.hpp"
#include "io/csv_input.hpp"
#include "json_reader.hpp"
#include "program_runner.hpp"

#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <gtest/gtest.h>

#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;
using obbsat::accuracy::double_corner_family_names;
using obbsat::accuracy::double_pose_family_names;
using obbsat::cli_test::json;
using obbsat::cli_test::json_reader;
using obbsat::cli_test::lines_of;
using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::oracle::contact;

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

std::vector<double> values_of(const rect_pose64& p) {
    return {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x, p.rotation.y};
}

std::vector<double> values_of(const rect64& r) {
    return {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
}

// Every field of every line of a shape file is the shortest text of its double.
void expect_shortest_round_trip(const std::string& text) {
    std::size_t checked = 0;
    for (const std::string& line : lines_of(text)) {
        std::size_t start = 0;
        while (start <= line.size()) {
            std::size_t comma = line.find(',', start);
            if (comma == std::string::npos) {
                comma = line.size();
            }
            const std::string field = line.substr(start, comma - start);
            double v = 0;
            const auto parsed = std::from_chars(field.data(), field.data() + field.size(), v);
            ASSERT_EQ(parsed.ptr, field.data() + field.size()) << field;
            char shortest[40];
            const std::string again(shortest, std::to_chars(shortest, shortest + sizeof shortest, v).ptr);
            EXPECT_EQ(field, again);
            ++checked;
            start = comma + 1;
        }
    }
    EXPECT_GT(checked, 0u);
}

char class_letter(contact c) { return c == contact::separated ? 'S' : c == contact::touching ? 'T' : 'O'; }

TEST(double_gen, writes_each_double_pose_family_with_the_double_oracles_truth) {
    const scratch s;
    for (std::size_t f = 0; f < double_pose_family_names().size(); ++f) {
        const std::string name(double_pose_family_names()[f]);
        const std::string dir = "d_" + name;
        const run_result r = s.run("gen --precision double --poses " + name + " --out " + dir + " --pairs 300 --seed 4");
        ASSERT_EQ(r.status, 0) << r.err;
        const obbsat::accuracy::double_pose_suite suite = obbsat::accuracy::make_double_pose_family(f, 4, 300);
        const std::string text = read_file(s.file(dir + "/poses.csv"));
        expect_shortest_round_trip(text);
        obbsat::io::line_reader lines(std::string_view(text), "poses.csv");
        const obbsat::pose_records64 poses = obbsat::io::read_pose_records64(lines);
        ASSERT_EQ(poses.size(), suite.poses.size()) << name;
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const std::vector<double> got = values_of(poses[i]), want = values_of(suite.poses[i]);
            for (std::size_t k = 0; k < got.size(); ++k) {
                ASSERT_TRUE(same_bits(got[k], want[k])) << name << " pose " << i << " field " << k;
            }
        }
        const auto classes = lines_of(read_file(s.file(dir + "/truth_class.txt")));
        const auto truth = lines_of(read_file(s.file(dir + "/truth.txt")));
        const auto tags = lines_of(read_file(s.file(dir + "/tags.txt")));
        ASSERT_EQ(classes.size(), 300u);
        ASSERT_EQ(tags.size(), 300u);
        for (std::size_t i = 0; i < 300; ++i) {
            const contact c = obbsat::oracle::classify(poses[2 * i], poses[2 * i + 1]);
            EXPECT_EQ(classes[i], std::string(1, class_letter(c))) << name << " pair " << i;
            EXPECT_EQ(truth[i], c == contact::separated ? "0" : "1");
            EXPECT_EQ(tags[i], name);
        }
        // collide --precision double reads the files back and exact prints the truth.
        const run_result exact = s.run("collide --poses " + dir + "/poses.csv --pairs " + dir +
                                       "/pairs.csv --precision double --method exact");
        ASSERT_EQ(exact.status, 0) << exact.err;
        EXPECT_EQ(exact.out, read_file(s.file(dir + "/truth.txt"))) << name;
    }
}

TEST(double_gen, writes_each_double_corner_family_and_hex_reads_back_to_the_same_answers) {
    const scratch s;
    for (std::size_t f = 0; f < double_corner_family_names().size(); ++f) {
        const std::string name(double_corner_family_names()[f]);
        const run_result r = s.run("gen --precision double " + name + " --out dec --pairs 200 --header");
        ASSERT_EQ(r.status, 0) << r.err;
        const run_result h = s.run("gen --precision double " + name + " --out hex --pairs 200 --hex");
        ASSERT_EQ(h.status, 0) << h.err;
        const obbsat::accuracy::double_rect_suite suite = obbsat::accuracy::make_double_corner_family(f, 1, 200);
        const std::string text = read_file(s.file("dec/rects.csv"));
        ASSERT_EQ(text.rfind("ulx,uly,urx,ury,lrx,lry,llx,lly\n", 0), 0u);
        expect_shortest_round_trip(text.substr(text.find('\n') + 1));
        for (const char* dir : {"dec", "hex"}) {
            const std::string shapes = read_file(s.file(std::string(dir) + "/rects.csv"));
            obbsat::io::line_reader lines(std::string_view(shapes), "rects.csv");
            const obbsat::rect_records64 rects = obbsat::io::read_rect_records64(lines);
            ASSERT_EQ(rects.size(), suite.rects.size());
            for (std::size_t i = 0; i < rects.size(); ++i) {
                const std::vector<double> got = values_of(rects[i]), want = values_of(suite.rects[i]);
                for (std::size_t k = 0; k < got.size(); ++k) {
                    ASSERT_TRUE(same_bits(got[k], want[k])) << name << " " << dir << " rect " << i;
                }
            }
            const run_result exact = s.run(std::string("collide --rects ") + dir + "/rects.csv --pairs " + dir +
                                           "/pairs.csv --precision double");
            ASSERT_EQ(exact.status, 0) << exact.err;
            EXPECT_EQ(exact.out, read_file(s.file("hex/truth.txt"))) << name << " " << dir;
        }
        std::string truth;
        for (std::size_t i = 0; i < suite.pairs.size(); ++i) {
            truth += obbsat::oracle::classify(suite.rects[2 * i], suite.rects[2 * i + 1]) == contact::separated ? "0\n"
                                                                                                               : "1\n";
        }
        EXPECT_EQ(read_file(s.file("dec/truth.txt")), truth) << name;
    }
}

TEST(double_gen, usage_errors_exit_2_and_write_nothing) {
    const scratch s;
    const run_result unknown = s.run("gen --precision double --poses tiles --out d");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.err.find("unknown double pose family 'tiles' (known: utm_random, utm_contact"),
              std::string::npos)
        << unknown.err;
    const run_result scene = s.run("gen --precision double --scene uniform --boxes 10");
    EXPECT_EQ(scene.status, 2);
    EXPECT_NE(scene.err.find("--scene with --precision double"), std::string::npos) << scene.err;
    const run_result word = s.run("gen utm_random --precision single --out d");
    EXPECT_EQ(word.status, 2);
    EXPECT_TRUE(s.tree().empty());
}

// ---------------------------------------------------------------------------
// accuracy --precision double.

std::optional<float> to_float(double v) {
    if (!(std::fabs(v) <= static_cast<double>(FLT_MAX))) {
        return std::nullopt;
    }
    return static_cast<float>(v);
}

std::optional<obbsat::rect_pose> rounded(const rect_pose64& p) {
    const std::vector<double> v = values_of(p);
    float f[6];
    for (std::size_t k = 0; k < 6; ++k) {
        const auto x = to_float(v[k]);
        if (!x) {
            return std::nullopt;
        }
        f[k] = *x;
    }
    if (f[4] == 0.0f && f[5] == 0.0f) {
        return std::nullopt;
    }
    return obbsat::rect_pose{{f[0], f[1]}, {f[2], f[3]}, {f[4], f[5]}};
}

std::optional<obbsat::rect> rounded(const rect64& r) {
    const std::vector<double> v = values_of(r);
    float f[8];
    for (std::size_t k = 0; k < 8; ++k) {
        const auto x = to_float(v[k]);
        if (!x) {
            return std::nullopt;
        }
        f[k] = *x;
    }
    return obbsat::rect{{f[0], f[1]}, {f[2], f[3]}, {f[4], f[5]}, {f[6], f[7]}};
}

struct counts {
    std::uint64_t pairs = 0, fp = 0, fn_touching = 0, fn_overlapping = 0;
    void add(contact truth, bool said) {
        ++pairs;
        fp += truth == contact::separated && said;
        fn_touching += truth == contact::touching && !said;
        fn_overlapping += truth == contact::overlapping && !said;
    }
};

// What row `label` says on pair (a, b), by the scalar references (float32
// exact: the float oracle on the rounded pair), or nothing when float32
// cannot hold the pair.
template <class Shape>
std::optional<bool> said_by(const std::string& label, const Shape& a, const Shape& b) {
    if (label.find("float32") != std::string::npos) {
        const auto fa = rounded(a), fb = rounded(b);
        if (!fa || !fb) {
            return std::nullopt;
        }
        return obbsat::oracle::classify(*fa, *fb) != contact::separated;
    }
    if (label.rfind("exact", 0) == 0) {
        return obbsat::ref::exact(a, b);
    }
    if (label.rfind("conservative", 0) == 0) {
        return obbsat::ref::conservative(a, b);
    }
    if constexpr (std::is_same_v<Shape, rect_pose64>) {
        return obbsat::ref::local(a, b);
    }
    ADD_FAILURE() << "no reference for " << label;
    return false;
}

template <class Suite>
void check_row(const json& row, const std::string& label, const Suite& suite, const json& family_counts,
               counts& total) {
    counts c;
    std::uint64_t dropped = 0;
    const auto& shapes = [&]() -> const auto& {
        if constexpr (std::is_same_v<Suite, obbsat::accuracy::double_pose_suite>) {
            return suite.poses;
        } else {
            return suite.rects;
        }
    }();
    for (const pair_index& p : suite.pairs) {
        const contact truth = obbsat::oracle::classify(shapes[p.a], shapes[p.b]);
        const std::optional<bool> said = said_by(label, shapes[p.a], shapes[p.b]);
        if (!said) {
            ++dropped;
            continue;
        }
        c.add(truth, *said);
        total.add(truth, *said);
    }
    const std::string where = label + " on " + suite.family;
    EXPECT_EQ(family_counts["family"].text, suite.family) << where;
    EXPECT_EQ(family_counts["pairs"].count(), c.pairs) << where;
    EXPECT_EQ(family_counts["false_positives"].count(), c.fp) << where;
    EXPECT_EQ(family_counts["false_negatives_touching"].count(), c.fn_touching) << where;
    EXPECT_EQ(family_counts["false_negatives_overlapping"].count(), c.fn_overlapping) << where;
    if (label.find("float32") == std::string::npos) {
        EXPECT_EQ(dropped, 0u) << where;
    }
    (void)row;
}

TEST(double_accuracy, json_holds_the_counts_the_double_references_give) {
    const scratch s;
    const run_result r = s.run("accuracy --precision double --pairs 150 --seed 3 --json acc.json --svg acc.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("summary over all families"), std::string::npos);
    EXPECT_NE(r.out.find("exact (float32 poses)"), std::string::npos);
    const std::string svg = read_file(s.file("acc.svg"));
    EXPECT_NE(svg.find("exact (double poses)"), std::string::npos);
    EXPECT_NE(svg.find("conservative (double corners)"), std::string::npos);
    const json report = json_reader(read_file(s.file("acc.json"))).document();
    ASSERT_EQ(report["pose_families"].items.size(), double_pose_family_names().size());
    ASSERT_EQ(report["families"].items.size(), double_corner_family_names().size());

    const std::vector<std::string> labels = {"conservative (double poses)",   "exact (double poses)",
                                             "local (double poses)",          "exact (float32 poses)",
                                             "conservative (double corners)", "exact (double corners)",
                                             "exact (float32 corners)"};
    ASSERT_EQ(report["methods"].items.size(), labels.size());
    std::uint64_t float32_errors = 0;
    for (std::size_t m = 0; m < labels.size(); ++m) {
        const json& row = report["methods"].items[m];
        EXPECT_EQ(row["label"].text, labels[m]);
        const bool poses = labels[m].find("poses") != std::string::npos;
        counts total;
        const std::size_t families = poses ? double_pose_family_names().size() : double_corner_family_names().size();
        ASSERT_EQ(row["families"].items.size(), families) << labels[m];
        for (std::size_t f = 0; f < families; ++f) {
            if (poses) {
                check_row(row, labels[m], obbsat::accuracy::make_double_pose_family(f, 3, 150),
                          row["families"].items[f], total);
            } else {
                check_row(row, labels[m], obbsat::accuracy::make_double_corner_family(f, 3, 150),
                          row["families"].items[f], total);
            }
        }
        const std::uint64_t errors = total.fp + total.fn_touching + total.fn_overlapping;
        EXPECT_EQ(row["total"]["errors"].count(), errors) << labels[m];
        if (labels[m].rfind("exact (double", 0) == 0) {
            EXPECT_EQ(errors, 0u) << labels[m];  // the double exact methods are the oracle's answer
        }
        if (labels[m].rfind("conservative", 0) == 0) {
            EXPECT_EQ(total.fn_touching + total.fn_overlapping, 0u) << labels[m];
        }
        if (labels[m].find("float32") != std::string::npos) {
            float32_errors += errors;
        }
    }
    // Rounding the same doubles to float32 makes exact wrong on many pairs.
    EXPECT_GT(float32_errors, 0u);
}

}  // namespace
