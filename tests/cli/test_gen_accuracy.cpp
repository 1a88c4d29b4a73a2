// The gen and accuracy commands run through the shell as a user runs them:
// gen's files are the library's suite byte for byte (of rects, or with
// --poses of poses), collide reads them, and their truth is the oracle's;
// gen's errors leave nothing behind; accuracy's JSON holds the counts the
// library's references give, for the methods on corners and on poses, and its
// SVG is well-formed with one point per method and store; demo prints the
// short form.
#include "io/csv_input.hpp"
#include "json_reader.hpp"
#include "program_runner.hpp"

#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/pose_family.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using obbsat::method;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::oracle::contact;
using obbsat::suites::family;
using obbsat::suites::pose_family;

using obbsat::cli_test::json;
using obbsat::cli_test::json_reader;
using obbsat::cli_test::lines_of;
using obbsat::cli_test::read_file;
using obbsat::cli_test::run_result;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

const char* const suite_files[] = {"rects.csv", "pairs.csv", "truth_class.txt", "truth.txt", "tags.txt"};
const char* const pose_suite_files[] = {"poses.csv", "pairs.csv", "truth_class.txt", "truth.txt", "tags.txt"};

std::string family_list() {
    std::string known;
    for (const family f : obbsat::suites::all_families()) {
        known += (known.empty() ? "" : ", ") + std::string(obbsat::suites::family_name(f));
    }
    return known;
}

std::string pose_family_list() {
    std::string known;
    for (const pose_family f : obbsat::suites::all_pose_families()) {
        known += (known.empty() ? "" : ", ") + std::string(obbsat::suites::pose_family_name(f));
    }
    return known;
}

// The poses of a pose file, read by the program's own reader.
std::vector<rect_pose> read_poses(const fs::path& path) {
    const std::string text = read_file(path);
    obbsat::io::line_reader lines(std::string_view(text), path.string());
    const obbsat::pose_records records = obbsat::io::read_pose_records(lines);
    std::vector<rect_pose> out;
    for (std::size_t i = 0; i < records.size(); ++i) {
        out.push_back(records[i]);
    }
    return out;
}

bool same_bits(float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; }

bool same_rect_bits(const rect& a, const rect& b) {
    return same_bits(a.ul.x, b.ul.x) && same_bits(a.ul.y, b.ul.y) && same_bits(a.ur.x, b.ur.x) &&
           same_bits(a.ur.y, b.ur.y) && same_bits(a.lr.x, b.lr.x) && same_bits(a.lr.y, b.lr.y) &&
           same_bits(a.ll.x, b.ll.x) && same_bits(a.ll.y, b.ll.y);
}

bool same_pose_bits(const rect_pose& a, const rect_pose& b) {
    return same_bits(a.center.x, b.center.x) && same_bits(a.center.y, b.center.y) &&
           same_bits(a.half_extents.x, b.half_extents.x) && same_bits(a.half_extents.y, b.half_extents.y) &&
           same_bits(a.rotation.x, b.rotation.x) && same_bits(a.rotation.y, b.rotation.y);
}

// ---------------------------------------------------------------------------
// A well-formedness check for the SVG: every tag closed in order, quotes
// balanced inside tags, no stray '<' or unescaped '&' in text.

struct xml_element {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;  // the text directly inside, for <text>
};

std::vector<xml_element> parse_xml_elements(const std::string& xml) {
    std::vector<xml_element> elements;
    std::vector<std::string> open;
    std::vector<std::size_t> open_index;
    std::size_t at = 0;
    if (xml.compare(0, 5, "<?xml") == 0) {
        at = xml.find("?>");
        if (at == std::string::npos) {
            throw std::runtime_error("unfinished XML declaration");
        }
        at += 2;
    }
    while (at < xml.size()) {
        const std::size_t lt = xml.find('<', at);
        const std::string text = xml.substr(at, lt == std::string::npos ? std::string::npos : lt - at);
        for (std::size_t amp = text.find('&'); amp != std::string::npos; amp = text.find('&', amp + 1)) {
            const std::size_t semi = text.find(';', amp);
            const std::string entity = text.substr(amp, semi == std::string::npos ? 1 : semi - amp + 1);
            if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" &&
                entity != "&apos;") {
                throw std::runtime_error("bad entity " + entity);
            }
        }
        if (!open_index.empty()) {
            elements[open_index.back()].text += text;
        } else if (text.find_first_not_of(" \t\r\n") != std::string::npos) {
            throw std::runtime_error("text outside the root: " + text);
        }
        if (lt == std::string::npos) {
            break;
        }
        // The tag ends at the first '>' outside quotes.
        std::size_t gt = lt + 1;
        bool quoted = false;
        while (gt < xml.size() && (quoted || xml[gt] != '>')) {
            if (xml[gt] == '"') {
                quoted = !quoted;
            } else if (xml[gt] == '<' && !quoted) {
                throw std::runtime_error("'<' inside a tag");
            }
            ++gt;
        }
        if (gt >= xml.size()) {
            throw std::runtime_error("unfinished tag");
        }
        std::string tag = xml.substr(lt + 1, gt - lt - 1);
        at = gt + 1;
        if (!tag.empty() && tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (open.empty() || open.back() != name) {
                throw std::runtime_error("</" + name + "> closes " + (open.empty() ? "nothing" : open.back()));
            }
            open.pop_back();
            open_index.pop_back();
            continue;
        }
        const bool self_closing = !tag.empty() && tag.back() == '/';
        if (self_closing) {
            tag.pop_back();
        }
        xml_element element;
        std::size_t pos = tag.find_first_of(" \t\n");
        element.name = tag.substr(0, pos);
        if (element.name.empty() || (elements.empty() && element.name != "svg")) {
            throw std::runtime_error("bad element name in <" + tag + ">");
        }
        while (pos != std::string::npos && pos < tag.size()) {
            const std::size_t name_start = tag.find_first_not_of(" \t\n", pos);
            if (name_start == std::string::npos) {
                break;
            }
            const std::size_t equals = tag.find("=\"", name_start);
            const std::size_t close = equals == std::string::npos ? std::string::npos : tag.find('"', equals + 2);
            if (close == std::string::npos) {
                throw std::runtime_error("bad attribute in <" + tag + ">");
            }
            element.attributes[tag.substr(name_start, equals - name_start)] =
                tag.substr(equals + 2, close - equals - 2);
            pos = close + 1;
        }
        if (!open.empty() || elements.empty()) {
            elements.push_back(element);
        } else {
            throw std::runtime_error("a second root element <" + element.name + ">");
        }
        if (!self_closing) {
            open.push_back(element.name);
            open_index.push_back(elements.size() - 1);
        }
    }
    if (!open.empty()) {
        throw std::runtime_error("<" + open.back() + "> never closed");
    }
    return elements;
}

// ===========================================================================
// gen

/// The four files gen writes beside the shapes (pairs, truth classes, truth,
/// tags), 300 pairs, against the suite asked for: `shapes` are its rects or
/// its poses, classified by the matching exact oracle.
template <class Suite, class Shapes>
void expect_truth_files(const scratch& s, const std::string& name, const Suite& want, const Shapes& shapes) {
    const std::vector<std::string> pairs = lines_of(read_file(s.file(name + "/pairs.csv")));
    const std::vector<std::string> classes = lines_of(read_file(s.file(name + "/truth_class.txt")));
    const std::vector<std::string> truth = lines_of(read_file(s.file(name + "/truth.txt")));
    const std::vector<std::string> tags = lines_of(read_file(s.file(name + "/tags.txt")));
    ASSERT_EQ(pairs.size(), 300u);
    ASSERT_EQ(classes.size(), 300u);
    ASSERT_EQ(truth.size(), 300u);
    ASSERT_EQ(tags.size(), 300u);
    for (std::size_t i = 0; i < 300; ++i) {
        const obbsat::pair_index p = want.pairs[i];
        EXPECT_EQ(pairs[i], std::to_string(p.a) + "," + std::to_string(p.b)) << name << " " << i;
        const contact c = obbsat::oracle::classify(shapes[p.a], shapes[p.b]);
        EXPECT_EQ(classes[i], std::string(1, obbsat::oracle::contact_letter(c))) << name << " " << i;
        EXPECT_EQ(truth[i], c == contact::separated ? "0" : "1") << name << " " << i;
        EXPECT_EQ(tags[i], want.tag_of(i)) << name << " " << i;
    }
}

TEST(gen, writes_the_suite_the_library_builds_with_the_oracles_truth) {
    const scratch s;
    for (const family f : obbsat::suites::all_families()) {
        const std::string name = obbsat::suites::family_name(f);
        const run_result r = s.run("gen " + name + " --out " + name + " --pairs 300 --seed 3");
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        EXPECT_EQ(r.err, "");
        const obbsat::suites::suite want = obbsat::suites::make_family(f, 3, 300);

        // Rects: read back by the program's own reader, bit for bit, subnormals included.
        const obbsat::rect_soa rects = obbsat::io::read_rects_file(s.file(name + "/rects.csv").string());
        ASSERT_EQ(rects.size(), want.rects.size()) << name;
        for (std::size_t i = 0; i < want.rects.size(); ++i) {
            ASSERT_TRUE(same_rect_bits(rects[i], want.rects[i])) << name << " rect " << i;
        }
        expect_truth_files(s, name, want, want.rects);
    }
}

TEST(gen, collide_reads_its_files_and_method_exact_prints_its_truth) {
    const scratch s;
    for (const family f : obbsat::suites::all_families()) {
        const std::string name = obbsat::suites::family_name(f);
        ASSERT_EQ(s.run("gen " + name + " --out d --pairs 2000").status, 0) << name;
        const std::string truth = read_file(s.file("d/truth.txt"));
        const run_result exact = s.run("collide --rects d/rects.csv --pairs d/pairs.csv --method exact");
        ASSERT_EQ(exact.status, 0) << name << ": " << exact.err;
        EXPECT_EQ(exact.out, truth) << name;

        // Every other method prints what its scalar reference says on the rects as read.
        const obbsat::rect_soa rects = obbsat::io::read_rects_file(s.file("d/rects.csv").string());
        const obbsat::suites::suite want = obbsat::suites::make_family(f, 1, 2000);
        for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            const run_result r = s.run("collide --rects d/rects.csv --pairs d/pairs.csv --method " +
                                       std::string(obbsat::method_name(m)));
            ASSERT_EQ(r.status, 0) << r.err;
            std::string expected;
            for (const obbsat::pair_index& p : want.pairs) {
                expected += obbsat::method_reference(m)(rects[p.a], rects[p.b]) ? "1\n" : "0\n";
            }
            EXPECT_EQ(r.out, expected) << name << " " << obbsat::method_name(m);
        }
    }
}

TEST(gen, is_deterministic_and_replaces_only_its_own_files_in_an_existing_directory) {
    const scratch s;
    fs::create_directory(s.file("d"));
    write_file(s.file("d/notes.txt"), "keep me\n");
    write_file(s.file("d/truth.txt"), "old\n");
    ASSERT_EQ(s.run("gen grazing --out d --pairs 100 --seed 9").status, 0);
    ASSERT_EQ(s.run("gen grazing --out fresh/ --pairs 100 --seed 9").status, 0);
    for (const char* name : suite_files) {
        EXPECT_EQ(read_file(s.file(std::string("d/") + name)), read_file(s.file(std::string("fresh/") + name)))
            << name;
    }
    EXPECT_EQ(read_file(s.file("d/notes.txt")), "keep me\n");
    // A new directory gets the permissions mkdir gives, not mkdtemp's 0700.
    fs::create_directory(s.file("probe"));
    EXPECT_EQ(fs::status(s.file("fresh")).permissions(), fs::status(s.file("probe")).permissions());
    fs::remove(s.file("probe"));
    const std::vector<std::string> expected = {"d",
                                               "d/notes.txt",
                                               "d/pairs.csv",
                                               "d/rects.csv",
                                               "d/tags.txt",
                                               "d/truth.txt",
                                               "d/truth_class.txt",
                                               "fresh",
                                               "fresh/pairs.csv",
                                               "fresh/rects.csv",
                                               "fresh/tags.txt",
                                               "fresh/truth.txt",
                                               "fresh/truth_class.txt"};
    EXPECT_EQ(s.tree(), expected);  // no temporary directory left behind
}

TEST(gen, family_placement_and_option_forms) {
    const scratch s;
    ASSERT_EQ(s.run("gen --out a --pairs=50 tiny").status, 0);
    ASSERT_EQ(s.run("gen tiny --pairs 50 --out=b").status, 0);
    EXPECT_EQ(read_file(s.file("a/rects.csv")), read_file(s.file("b/rects.csv")));
    EXPECT_EQ(lines_of(read_file(s.file("a/tags.txt"))).size(), 50u);
}

TEST(gen, usage_errors_exit_2_with_the_reason_and_write_nothing) {
    const scratch s;
    write_file(s.file("R.csv"), "0,1,1,1,1,0,0,0\n");
    const std::string see = " (see 'obbsat gen --help')\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"gen --out d", "missing FAMILY (one of " + family_list() + ")"},
        {"gen tilez --out d", "unknown family 'tilez' (known: " + family_list() + ")"},
        {"gen tiles", "missing required option --out"},
        {"gen tiles grazing --out d", "unexpected argument 'grazing'"},
        {"gen tiles --out d --pairs 0", "--pairs: expected a whole number from 1 to 100000000, got '0'"},
        {"gen tiles --out d --pairs 1e3", "--pairs: expected a whole number from 1 to 100000000, got '1e3'"},
        {"gen tiles --out d --seed -1",
         "--seed: expected a whole number from 0 to 18446744073709551615, got '-1'"},
        {"gen tiles --out d --colour red", "unknown option --colour"},
        {"gen tiles --out d --out e", "option --out given twice"},
    };
    for (const auto& [args, reason] : cases) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "obbsat: gen: " + reason + see) << args;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(s.tree(), std::vector<std::string>{"R.csv"}) << args;
    }
}

TEST(gen, output_errors_exit_2_name_the_path_and_leave_everything_as_it_was) {
    const scratch s;
    write_file(s.file("R.csv"), "0,1,1,1,1,0,0,0\n");
    {
        const run_result r = s.run("gen tiles --out R.csv");
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err, "obbsat: R.csv: exists and is not a directory\n");
    }
    {
        const run_result r = s.run("gen tiles --out R.csv/sub");
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err, "obbsat: R.csv/sub: cannot create a temporary directory for it: Not a directory\n");
    }
    {
        const run_result r = s.run("gen tiles --out missing/sub");
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.err,
                  "obbsat: missing/sub: cannot create a temporary directory for it: No such file or directory\n");
    }
    EXPECT_EQ(s.tree(), std::vector<std::string>{"R.csv"});
    EXPECT_EQ(read_file(s.file("R.csv")), "0,1,1,1,1,0,0,0\n");

    // A name of the suite taken by a directory: refused before any file moves.
    fs::create_directories(s.file("d/tags.txt"));
    write_file(s.file("d/rects.csv"), "old\n");
    const run_result r = s.run("gen tiles --out d");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "obbsat: d/tags.txt: is a directory, not a file name\n");
    EXPECT_EQ(read_file(s.file("d/rects.csv")), "old\n");
    const std::vector<std::string> expected = {"R.csv", "d", "d/rects.csv", "d/tags.txt"};
    EXPECT_EQ(s.tree(), expected);
}

// ===========================================================================
// gen --poses

TEST(gen_poses, writes_the_pose_suite_the_library_builds_with_the_pose_oracles_truth) {
    const scratch s;
    for (const pose_family f : obbsat::suites::all_pose_families()) {
        const std::string name = obbsat::suites::pose_family_name(f);
        const run_result r = s.run("gen --poses " + name + " --out " + name + " --pairs 300 --seed 3");
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        EXPECT_EQ(r.err, "");
        EXPECT_EQ(r.out, name + ": 300 pairs of pose family " + name + " (seed 3) over 600 poses\n");
        EXPECT_FALSE(fs::exists(s.file(name + "/rects.csv"))) << name;
        const obbsat::suites::pose_suite want = obbsat::suites::make_pose_family(f, 3, 300);

        // Poses: read back by the program's own reader, bit for bit.
        const std::vector<rect_pose> poses = read_poses(s.file(name + "/poses.csv"));
        ASSERT_EQ(poses.size(), want.poses.size()) << name;
        for (std::size_t i = 0; i < want.poses.size(); ++i) {
            ASSERT_TRUE(same_pose_bits(poses[i], want.poses[i])) << name << " pose " << i;
        }
        expect_truth_files(s, name, want, want.poses);
    }
}

TEST(gen_poses, collide_poses_reads_its_files_and_every_pose_method_prints_its_reference) {
    const scratch s;
    for (const pose_family f : obbsat::suites::all_pose_families()) {
        const std::string name = obbsat::suites::pose_family_name(f);
        ASSERT_EQ(s.run("gen --poses " + name + " --out d --pairs 2000").status, 0) << name;
        const std::string truth = read_file(s.file("d/truth.txt"));
        const run_result exact = s.run("collide --poses d/poses.csv --pairs d/pairs.csv --method exact");
        ASSERT_EQ(exact.status, 0) << name << ": " << exact.err;
        EXPECT_EQ(exact.out, truth) << name;

        // Every method on poses prints what its scalar reference says on the
        // poses as read; local, collide's default on poses, without --method too.
        const std::vector<rect_pose> poses = read_poses(s.file("d/poses.csv"));
        const obbsat::suites::pose_suite want = obbsat::suites::make_pose_family(f, 1, 2000);
        for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
            const run_result r = s.run("collide --poses d/poses.csv --pairs d/pairs.csv --method " +
                                       std::string(obbsat::method_name(m)));
            ASSERT_EQ(r.status, 0) << r.err;
            std::string expected;
            for (const obbsat::pair_index& p : want.pairs) {
                expected += obbsat::pose_method_reference(m)(poses[p.a], poses[p.b]) ? "1\n" : "0\n";
            }
            EXPECT_EQ(r.out, expected) << name << " " << obbsat::method_name(m);
            if (m == method::local) {
                EXPECT_EQ(s.run("collide --poses d/poses.csv --pairs d/pairs.csv").out, expected) << name;
            }
        }
    }
}

TEST(gen_poses, is_deterministic_and_leaves_the_other_files_of_a_directory_alone) {
    const scratch s;
    // A pose family beside a corner family of the same name in one directory:
    // the pose files replace pairs, truth and tags and leave rects.csv.
    ASSERT_EQ(s.run("gen tiny --out d --pairs 100").status, 0);
    const std::string rects = read_file(s.file("d/rects.csv"));
    ASSERT_EQ(s.run("gen tiny --poses --out d --pairs=100 --seed 9").status, 0);
    ASSERT_EQ(s.run("gen --out=fresh/ --seed 9 --poses tiny --pairs 100").status, 0);
    for (const char* name : pose_suite_files) {
        EXPECT_EQ(read_file(s.file(std::string("d/") + name)), read_file(s.file(std::string("fresh/") + name)))
            << name;
    }
    EXPECT_EQ(read_file(s.file("d/rects.csv")), rects);
    const std::vector<std::string> expected = {"d",
                                               "d/pairs.csv",
                                               "d/poses.csv",
                                               "d/rects.csv",
                                               "d/tags.txt",
                                               "d/truth.txt",
                                               "d/truth_class.txt",
                                               "fresh",
                                               "fresh/pairs.csv",
                                               "fresh/poses.csv",
                                               "fresh/tags.txt",
                                               "fresh/truth.txt",
                                               "fresh/truth_class.txt"};
    EXPECT_EQ(s.tree(), expected);  // no temporary directory left behind
}

TEST(gen_poses, usage_and_output_errors_exit_2_and_write_nothing) {
    const scratch s;
    write_file(s.file("R.csv"), "0,1,1,1,1,0,0,0\n");
    const std::string see = " (see 'obbsat gen --help')\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"gen --poses --out d", "missing FAMILY (one of " + pose_family_list() + ")"},
        {"gen --poses tiles --out d", "unknown pose family 'tiles' (known: " + pose_family_list() + ")"},
        {"gen --poses=yes near --out d", "option --poses takes no value"},
        {"gen --poses near --poses --out d", "option --poses given twice"},
        {"gen near --out d", "unknown family 'near' (known: " + family_list() + ")"},
        {"gen --poses near contact --out d", "unexpected argument 'contact'"},
    };
    for (const auto& [args, reason] : cases) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "obbsat: gen: " + reason + see) << args;
        EXPECT_EQ(r.out, "") << args;
        EXPECT_EQ(s.tree(), std::vector<std::string>{"R.csv"}) << args;
    }
    // The pose file's name taken by a directory: refused before any file moves.
    fs::create_directories(s.file("d/poses.csv"));
    write_file(s.file("d/pairs.csv"), "old\n");
    const run_result r = s.run("gen --poses contact --out d");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "obbsat: d/poses.csv: is a directory, not a file name\n");
    EXPECT_EQ(read_file(s.file("d/pairs.csv")), "old\n");
    const std::vector<std::string> expected = {"R.csv", "d", "d/pairs.csv", "d/poses.csv"};
    EXPECT_EQ(s.tree(), expected);
}

// ===========================================================================
// accuracy

// One row of the report as the test recomputes it: a method on a store, and
// per family of that store the pairs' truth and the reference's verdicts.
struct expected_row {
    method test;
    obbsat::store_kind store;
    std::string label;
    std::vector<std::string> family_names;
    std::vector<std::vector<contact>> truths;
    std::vector<std::vector<bool>> said;
};

TEST(accuracy, json_holds_the_counts_the_references_give_and_svg_is_well_formed) {
    const scratch s;
    const run_result r = s.run("accuracy --pairs 400 --seed 5 --threads 2 --reps 1 --json out/acc.json "
                               "--svg acc.svg");
    // The --json directory does not exist: nothing is measured or written.
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("out/acc.json"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(s.tree().empty());

    fs::create_directory(s.file("out"));
    const run_result ok = s.run("accuracy --pairs 400 --seed 5 --threads 2 --reps 1 --json out/acc.json "
                                "--svg acc.svg");
    ASSERT_EQ(ok.status, 0) << ok.err;
    const json report = json_reader(read_file(s.file("out/acc.json"))).document();
    EXPECT_EQ(report["format"].text, "obbsat-accuracy-2");
    EXPECT_EQ(report["pairs_per_family"].count(), 400u);
    EXPECT_EQ(report["seed"].count(), 5u);
    EXPECT_EQ(report["throughput_scene"]["store"].text, "rect_records");
    EXPECT_EQ(report["throughput_scene"]["pose_store"].text, "pose_records");

    // The truth and every count, recomputed here from the suites, the
    // oracles and each method's scalar reference: the methods on corners on
    // the corner families, then the methods on poses on the pose families.
    std::vector<expected_row> rows;
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        rows.push_back({m, obbsat::store_kind::corners, obbsat::method_name(m), {}, {}, {}});
    }
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        rows.push_back({m, obbsat::store_kind::poses, obbsat::method_name(m) + std::string(" (poses)"), {}, {}, {}});
    }
    auto check_truth = [](const json& t, const std::string& name, const std::vector<contact>& truth) {
        std::uint64_t by_class[3] = {0, 0, 0};
        for (const contact c : truth) {
            ++by_class[static_cast<int>(c)];
        }
        EXPECT_EQ(t["name"].text, name);
        EXPECT_EQ(t["pairs"].count(), 400u) << name;
        EXPECT_EQ(t["separated"].count(), by_class[0]) << name;
        EXPECT_EQ(t["touching"].count(), by_class[1]) << name;
        EXPECT_EQ(t["overlapping"].count(), by_class[2]) << name;
    };
    const std::vector<family>& families = obbsat::suites::all_families();
    ASSERT_EQ(report["families"].items.size(), families.size());
    for (std::size_t f = 0; f < families.size(); ++f) {
        const obbsat::suites::suite suite = obbsat::suites::make_family(families[f], 5, 400);
        std::vector<contact> truth;
        for (const obbsat::pair_index& p : suite.pairs) {
            truth.push_back(obbsat::oracle::classify(suite.rects[p.a], suite.rects[p.b]));
        }
        check_truth(report["families"].items[f], obbsat::suites::family_name(families[f]), truth);
        for (expected_row& row : rows) {
            if (row.store != obbsat::store_kind::corners) {
                continue;
            }
            std::vector<bool> said;
            for (const obbsat::pair_index& p : suite.pairs) {
                said.push_back(obbsat::method_reference(row.test)(suite.rects[p.a], suite.rects[p.b]));
            }
            row.family_names.push_back(obbsat::suites::family_name(families[f]));
            row.truths.push_back(truth);
            row.said.push_back(said);
        }
    }
    const std::vector<pose_family>& pose_families = obbsat::suites::all_pose_families();
    ASSERT_EQ(report["pose_families"].items.size(), pose_families.size());
    for (std::size_t f = 0; f < pose_families.size(); ++f) {
        const obbsat::suites::pose_suite suite = obbsat::suites::make_pose_family(pose_families[f], 5, 400);
        std::vector<contact> truth;
        for (const obbsat::pair_index& p : suite.pairs) {
            truth.push_back(obbsat::oracle::classify(suite.poses[p.a], suite.poses[p.b]));
        }
        check_truth(report["pose_families"].items[f], obbsat::suites::pose_family_name(pose_families[f]), truth);
        for (expected_row& row : rows) {
            if (row.store != obbsat::store_kind::poses) {
                continue;
            }
            std::vector<bool> said;
            for (const obbsat::pair_index& p : suite.pairs) {
                said.push_back(obbsat::pose_method_reference(row.test)(suite.poses[p.a], suite.poses[p.b]));
            }
            row.family_names.push_back(obbsat::suites::pose_family_name(pose_families[f]));
            row.truths.push_back(truth);
            row.said.push_back(said);
        }
    }

    ASSERT_EQ(report["methods"].items.size(), rows.size());
    for (std::size_t m = 0; m < rows.size(); ++m) {
        const expected_row& row = rows[m];
        const json& result = report["methods"].items[m];
        EXPECT_EQ(result["name"].text, obbsat::method_name(row.test));
        EXPECT_EQ(result["store"].text, obbsat::store_name(row.store));
        EXPECT_EQ(result["label"].text, row.label);
        EXPECT_EQ(result["mpairs_per_second"].type, json::kind::number) << row.label;
        EXPECT_GT(result["mpairs_per_second"].value, 0.0) << row.label;
        ASSERT_EQ(result["families"].items.size(), row.family_names.size()) << row.label;
        std::uint64_t total_fp = 0, total_fn = 0;
        for (std::size_t f = 0; f < row.family_names.size(); ++f) {
            std::uint64_t fp = 0, fn_touching = 0, fn_overlapping = 0;
            for (std::size_t i = 0; i < row.said[f].size(); ++i) {
                const bool said = row.said[f][i];
                fp += row.truths[f][i] == contact::separated && said;
                fn_touching += row.truths[f][i] == contact::touching && !said;
                fn_overlapping += row.truths[f][i] == contact::overlapping && !said;
            }
            const json& counts = result["families"].items[f];
            const std::string where = row.label + " on " + row.family_names[f];
            EXPECT_EQ(counts["family"].text, row.family_names[f]) << where;
            EXPECT_EQ(counts["pairs"].count(), 400u) << where;
            EXPECT_GT(counts["mpairs_per_second"].value, 0.0) << where;
            EXPECT_EQ(counts["false_positives"].count(), fp) << where;
            EXPECT_EQ(counts["false_negatives_touching"].count(), fn_touching) << where;
            EXPECT_EQ(counts["false_negatives_overlapping"].count(), fn_overlapping) << where;
            EXPECT_EQ(counts["false_negatives"].count(), fn_touching + fn_overlapping) << where;
            EXPECT_EQ(counts["errors"].count(), fp + fn_touching + fn_overlapping) << where;
            EXPECT_EQ(counts["error_rate"].value, static_cast<double>(fp + fn_touching + fn_overlapping) / 400.0)
                << where;
            if (row.test != method::exact) {
                EXPECT_EQ(counts["slow_path_pairs"].count(), 0u) << where;
            } else {
                EXPECT_LE(counts["slow_path_pairs"].count(), 400u) << where;
            }
            total_fp += fp;
            total_fn += fn_touching + fn_overlapping;
        }
        EXPECT_EQ(result["total"]["pairs"].count(), 400u * row.family_names.size()) << row.label;
        EXPECT_EQ(result["total"]["false_positives"].count(), total_fp) << row.label;
        EXPECT_EQ(result["total"]["false_negatives"].count(), total_fn) << row.label;
        if (row.test == method::exact) {
            EXPECT_EQ(result["total"]["errors"].count(), 0u) << row.label;
            EXPECT_GT(result["total"]["slow_path_pairs"].count(), 0u) << row.label;  // the suites sit on the boundary
        }
        if (row.test == method::conservative) {
            EXPECT_EQ(result["total"]["false_negatives"].count(), 0u) << row.label;
        }
        // The summary line on stdout names the row and its totals.
        char summary[160];
        std::snprintf(summary, sizeof summary, "\n  %-20s %9u ", row.label.c_str(),
                      static_cast<unsigned>(400u * row.family_names.size()));
        EXPECT_NE(ok.out.find(summary), std::string::npos) << summary << "\n" << ok.out;
        // So does its table.
        const std::string table = "\nmethod " + row.label +
                                  (row.store == obbsat::store_kind::poses ? ", on the pose families:\n" : ":\n");
        EXPECT_NE(ok.out.find(table), std::string::npos) << table;
    }
    EXPECT_NE(ok.out.find("\n  all pose families      4000 "), std::string::npos) << ok.out;

    // The plot: well-formed, one point and one label per method and store, nothing else plotted.
    const std::vector<xml_element> elements = parse_xml_elements(read_file(s.file("acc.svg")));
    ASSERT_FALSE(elements.empty());
    EXPECT_EQ(elements.front().name, "svg");
    EXPECT_EQ(elements.front().attributes.at("xmlns"), "http://www.w3.org/2000/svg");
    std::map<std::string, int> points, labels;
    for (const xml_element& e : elements) {
        const auto cls = e.attributes.find("class");
        if (cls == e.attributes.end()) {
            continue;
        }
        if (e.name == "circle" && cls->second.rfind("point", 0) == 0) {
            ++points[e.attributes.at("data-method")];
            EXPECT_GE(std::stod(e.attributes.at("cx")), 0.0);
            EXPECT_GE(std::stod(e.attributes.at("cy")), 0.0);
        }
        if (e.name == "text" && cls->second == "label") {
            ++labels[e.attributes.at("data-method")];
            EXPECT_EQ(e.text.rfind(e.attributes.at("data-method") + " (", 0), 0u) << e.text;
        }
    }
    ASSERT_EQ(points.size(), rows.size());
    ASSERT_EQ(labels.size(), rows.size());
    for (const expected_row& row : rows) {
        EXPECT_EQ(points[row.label], 1) << row.label;
        EXPECT_EQ(labels[row.label], 1) << row.label;
    }
}

TEST(accuracy, usage_errors_exit_2) {
    const scratch s;
    const std::string see = " (see 'obbsat accuracy --help')\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"accuracy --pairs 0", "--pairs: expected a whole number from 1 to 10000000, got '0'"},
        {"accuracy --threads many", "--threads: expected a whole number from 0 to 1024, got 'many'"},
        {"accuracy --reps 0", "--reps: expected a whole number from 1 to 1000, got '0'"},
        {"accuracy tiles", "unexpected argument 'tiles'"},
        {"accuracy --svg", "option --svg needs a value (FILE)"},
    };
    for (const auto& [args, reason] : cases) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "obbsat: accuracy: " + reason + see) << args;
        EXPECT_EQ(r.out, "") << args;
    }
    EXPECT_TRUE(s.tree().empty());
}

TEST(accuracy, help_and_the_program_help_name_both_commands) {
    const scratch s;
    for (const char* args : {"gen --help", "accuracy --help"}) {
        const run_result r = s.run(args);
        EXPECT_EQ(r.status, 0) << args;
        EXPECT_NE(r.out.find("usage: obbsat"), std::string::npos) << args;
        EXPECT_NE(r.out.find("example:\n  obbsat"), std::string::npos) << args;
    }
    EXPECT_NE(s.run("gen --help").out.find(family_list()), std::string::npos);
    EXPECT_NE(s.run("gen --help").out.find("pose families: " + pose_family_list()), std::string::npos);
    const run_result main_help = s.run("--help");
    EXPECT_NE(main_help.out.find("\n  gen "), std::string::npos) << main_help.out;
    EXPECT_NE(main_help.out.find("\n  accuracy "), std::string::npos) << main_help.out;
}

TEST(demo, prints_one_accuracy_line_per_method_and_store) {
    const scratch s;
    const run_result r = s.run("demo --rects 2000 --pairs 10000 --reps 1 --method all");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::size_t start = r.out.find("accuracy against the exact oracle: 2000 pairs of each of 11 hard-case "
                                         "families (methods on poses: of each of 10 pose families;");
    ASSERT_NE(start, std::string::npos) << r.out;
    const std::vector<std::string> lines = lines_of(r.out.substr(start));
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        // The methods on poses: scored on the pose families, timed on the
        // accuracy scene's rects as poses; this demo times them on no record store.
        char name[32];
        std::snprintf(name, sizeof name, "  %-20s ", (obbsat::method_name(m) + std::string(" (poses)")).c_str());
        const auto line = std::find_if(lines.begin(), lines.end(),
                                       [&](const std::string& l) { return l.rfind(name, 0) == 0; });
        ASSERT_NE(line, lines.end()) << name << "\n" << r.out;
        std::istringstream fields(line->substr(std::strlen(name)));
        std::string rate, false_negatives, speed, demo_speed;
        fields >> rate >> false_negatives >> speed >> demo_speed;
        EXPECT_GT(std::stod(speed), 0.0) << *line;
        EXPECT_EQ(demo_speed, "-") << *line;
        if (m == method::exact) {
            EXPECT_EQ(rate, "0") << *line;
        }
        if (m == method::exact || m == method::conservative) {
            EXPECT_EQ(false_negatives, "0") << *line;
        }
    }
    for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
        const std::string prefix = "  " + std::string(obbsat::method_name(m)) + " ";
        const auto line = std::find_if(lines.begin(), lines.end(),
                                       [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
        ASSERT_NE(line, lines.end()) << obbsat::method_name(m) << "\n" << r.out;
        std::istringstream fields(line->substr(prefix.size()));
        std::string rate, false_negatives, speed, demo_speed;
        fields >> rate >> false_negatives >> speed >> demo_speed;
        EXPECT_GT(std::stod(speed), 0.0) << *line;
        EXPECT_GT(std::stod(demo_speed), 0.0) << *line;  // --method all: the demo timed every method
        if (m == method::exact) {
            EXPECT_EQ(rate, "0") << *line;
        }
        if (m == method::exact || m == method::conservative) {
            EXPECT_EQ(false_negatives, "0") << *line;
        }
    }
}

}  // namespace
