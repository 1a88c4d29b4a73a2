// `obbsat contacts` and `obbsat distance`, run as a user runs them: every
// value read back from the output equals, bit for bit, what the library's
// find_contacts, contact_pairs and distance_pairs give on the same boxes;
// which pairs are written (a scene, a list, a margin); the header; errors with
// file and line and nothing written.
#include "program_runner.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::cli_test::lines_of;
using obbsat::cli_test::read_file;
using obbsat::cli_test::scratch;
using obbsat::cli_test::write_file;

std::vector<rect_pose> scene_rows() {
    obbsat::pose_scene_spec spec;
    spec.seed = 21;
    spec.boxes = 400;
    spec.sizes = obbsat::scene_sizes::mixed;
    spec.pairs_per_box = 2.0;
    return obbsat::make_pose_scene(spec);
}

std::string pose_file(const std::vector<rect_pose>& rows) {
    std::string text;
    char line[256];
    for (const rect_pose& p : rows) {
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a\n", double{p.center.x}, double{p.center.y},
                      double{p.half_extents.x}, double{p.half_extents.y}, double{p.rotation.x},
                      double{p.rotation.y});
        text += line;
    }
    return text;
}

std::vector<std::string> fields_of(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) {
        fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',') {
        fields.emplace_back();
    }
    return fields;
}

/// The float a field holds, bit for bit as read back.
std::uint32_t bits_of(const std::string& field) {
    char* end = nullptr;
    const float value = std::strtof(field.c_str(), &end);
    EXPECT_EQ(end, field.c_str() + field.size()) << "not a number: '" << field << "'";
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

std::uint32_t bits_of(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

/// Checks one output line against the pair and its contact.
void expect_line(const std::string& line, const pair_index& pair, const contact& c) {
    const std::vector<std::string> f = fields_of(line);
    ASSERT_EQ(f.size(), 12u) << line;
    EXPECT_EQ(f[0], std::to_string(pair.a)) << line;
    EXPECT_EQ(f[1], std::to_string(pair.b)) << line;
    EXPECT_EQ(bits_of(f[2]), bits_of(c.nx)) << line;
    EXPECT_EQ(bits_of(f[3]), bits_of(c.ny)) << line;
    EXPECT_EQ(bits_of(f[4]), bits_of(c.depth)) << line;
    EXPECT_EQ(f[5], std::to_string(c.point_count)) << line;
    for (std::uint32_t p = 0; p < 2; ++p) {
        if (p < c.point_count) {
            EXPECT_EQ(bits_of(f[6 + 3 * p]), bits_of(c.points[p].x)) << line;
            EXPECT_EQ(bits_of(f[7 + 3 * p]), bits_of(c.points[p].y)) << line;
            EXPECT_EQ(bits_of(f[8 + 3 * p]), bits_of(c.points[p].separation)) << line;
        } else {
            EXPECT_EQ(f[6 + 3 * p] + f[7 + 3 * p] + f[8 + 3 * p], "") << line;
        }
    }
}

obbsat::collide_options exact() {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    return options;
}

TEST(Contacts, SceneLinesAreFindContactsBitForBit) {
    scratch s;
    const std::vector<rect_pose> rows = scene_rows();
    write_file(s.file("poses.csv"), pose_file(rows));
    for (const char* margin : {"0", "0.125"}) {
        SCOPED_TRACE(margin);
        const auto r = s.run(std::string("contacts --poses poses.csv --threads 2 --margin ") + margin);
        ASSERT_EQ(r.status, 0) << r.err;
        const obbsat::scene_contacts expected = obbsat::find_contacts(rows, exact(), std::strtof(margin, nullptr));
        const std::vector<std::string> lines = lines_of(r.out);
        ASSERT_EQ(lines.size(), expected.pairs.size());
        ASSERT_FALSE(lines.empty());
        for (std::size_t k = 0; k < lines.size(); ++k) {
            expect_line(lines[k], expected.pairs[k], expected.contacts[k]);
        }
    }
    const auto near = s.run("contacts --poses poses.csv --margin 0.125");
    const auto touching = s.run("contacts --poses poses.csv");
    EXPECT_GT(lines_of(near.out).size(), lines_of(touching.out).size());
}

TEST(Contacts, MethodChoosesTheScenePairs) {
    scratch s;
    const std::vector<rect_pose> rows = scene_rows();
    write_file(s.file("poses.csv"), pose_file(rows));
    for (const obbsat::method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        const std::string name = obbsat::method_name(m);
        SCOPED_TRACE(name);
        const auto r = s.run("contacts --poses poses.csv --method " + name);
        ASSERT_EQ(r.status, 0) << r.err;
        obbsat::collide_options options;
        options.test = m;
        const obbsat::scene_contacts expected = obbsat::find_contacts(rows, options);
        const std::vector<std::string> lines = lines_of(r.out);
        ASSERT_EQ(lines.size(), expected.pairs.size());
        for (std::size_t k = 0; k < lines.size(); ++k) {
            expect_line(lines[k], expected.pairs[k], expected.contacts[k]);
        }
    }
    // Pair (0, 1) is apart by 2.4e-7, which conservative cannot prove in
    // float: it reports the pair, exact (the default) does not.
    write_file(s.file("near.csv"), "0,0,1,1,1,0\n2.0000002,0,1,1,1,0\n0,5,1,1,0.6,0.8\n");
    const auto by_default = s.run("contacts --poses near.csv");
    const auto by_exact = s.run("contacts --poses near.csv --method exact");
    const auto by_conservative = s.run("contacts --poses near.csv --method conservative");
    ASSERT_EQ(by_conservative.status, 0) << by_conservative.err;
    EXPECT_EQ(by_default.out, "");
    EXPECT_EQ(by_exact.out, "");
    ASSERT_EQ(lines_of(by_conservative.out).size(), 1u);
    EXPECT_EQ(fields_of(by_conservative.out).at(0), "0");
}

TEST(Contacts, ListLinesAreThePairsWithPointsInListOrder) {
    scratch s;
    // Overlapping, apart by 0.1, apart by 1.6; the list runs backwards.
    write_file(s.file("poses.csv"), "cx,cy,hx,hy,c,s\n0,0,1,1,1,0\n1.5,0,1,1,1,0\n3.6,0,1,1,1,0\n");
    write_file(s.file("pairs.csv"), "1,2\n0,2\n1,0\n");
    const std::vector<rect_pose> rows = {
        {{0, 0}, {1, 1}, {1, 0}}, {{1.5f, 0}, {1, 1}, {1, 0}}, {{3.6f, 0}, {1, 1}, {1, 0}}};
    const obbsat::pose_records store(rows);
    const std::vector<pair_index> pairs = {{1, 2}, {0, 2}, {1, 0}};

    const auto r = s.run("contacts --poses poses.csv --pairs pairs.csv --header");
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "i,j,nx,ny,depth,count,x1,y1,s1,x2,y2,s2");
    expect_line(lines[1], pairs[2], obbsat::contact_pairs(store, {pairs[2]})[0]);

    obbsat::contact_options options;
    options.margin = 0.2f;
    const auto near = s.run("contacts --poses poses.csv --pairs pairs.csv --margin 0.2");
    ASSERT_EQ(near.status, 0) << near.err;
    lines = lines_of(near.out);
    const std::vector<contact> contacts = obbsat::contact_pairs(store, pairs, options);
    ASSERT_EQ(lines.size(), 2u);
    expect_line(lines[0], pairs[0], contacts[0]);
    expect_line(lines[1], pairs[2], contacts[2]);
}

TEST(Contacts, CornerFileMatchesContactPairs) {
    scratch s;
    write_file(s.file("rects.csv"), "0,1,2,1,2,0,0,0\n1,2,3,2,3,0.5,1,0.5\n");
    const auto r = s.run("contacts --rects rects.csv --out c.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    const obbsat::rect rects[] = {{{0, 1}, {2, 1}, {2, 0}, {0, 0}}, {{1, 2}, {3, 2}, {3, 0.5f}, {1, 0.5f}}};
    const obbsat::rect_records store(rects, 2);
    const std::vector<std::string> lines = lines_of(read_file(s.file("c.csv")));
    ASSERT_EQ(lines.size(), 1u);
    expect_line(lines[0], {0, 1}, obbsat::contact_pairs(store, {{0, 1}})[0]);
}

TEST(Distance, LinesAreDistancePairsBitForBit) {
    scratch s;
    const std::vector<rect_pose> rows = scene_rows();
    write_file(s.file("poses.csv"), pose_file(rows));
    std::string pair_text;
    std::vector<pair_index> pairs;
    for (std::uint32_t k = 0; k < 300; ++k) {
        const pair_index p{(k * 7) % 400, (k * 13 + 5) % 400};
        pairs.push_back(p);
        pair_text += std::to_string(p.a) + "," + std::to_string(p.b) + "\n";
    }
    write_file(s.file("pairs.csv"), pair_text);
    const auto r = s.run("distance --poses poses.csv --pairs pairs.csv --header");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<obbsat::closest_points> expected =
        obbsat::distance_pairs(obbsat::pose_records(rows), pairs);
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), pairs.size() + 1);
    EXPECT_EQ(lines[0], "i,j,distance,ax,ay,bx,by");
    std::size_t colliding = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::vector<std::string> f = fields_of(lines[k + 1]);
        ASSERT_EQ(f.size(), 7u) << lines[k + 1];
        EXPECT_EQ(f[0], std::to_string(pairs[k].a));
        EXPECT_EQ(f[1], std::to_string(pairs[k].b));
        const obbsat::closest_points& e = expected[k];
        const float values[] = {e.distance, e.ax, e.ay, e.bx, e.by};
        for (std::size_t v = 0; v < 5; ++v) {
            EXPECT_EQ(bits_of(f[2 + v]), bits_of(values[v])) << lines[k + 1];
        }
        colliding += e.distance == 0.0f;
    }
    EXPECT_GT(colliding, 0u);  // pairs (k, k) at least
    EXPECT_LT(colliding, pairs.size());
}

/// UTM-like double poses (eastings near 5e5, northings near 5e6): float32
/// would round them by up to half a metre, more than their sizes' digits.
std::vector<obbsat::rect_pose64> utm_rows() {
    std::vector<obbsat::rect_pose64> rows;
    for (std::uint32_t k = 0; k < 60; ++k) {
        const double angle = 0.1 * k;
        rows.push_back({{500000.125 + 1.37 * k, 5000000.375 + 0.61 * (k % 7)},
                        {0.8 + 0.01 * k, 0.5},
                        {std::cos(angle), std::sin(angle)}});
    }
    return rows;
}

std::string pose64_file(const std::vector<obbsat::rect_pose64>& rows) {
    std::string text;
    char line[256];
    for (const obbsat::rect_pose64& p : rows) {
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a\n", p.center.x, p.center.y, p.half_extents.x,
                      p.half_extents.y, p.rotation.x, p.rotation.y);
        text += line;
    }
    return text;
}

/// The double a field holds, exactly as read back.
double double_of(const std::string& field) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    EXPECT_EQ(end, field.c_str() + field.size()) << "not a number: '" << field << "'";
    return value;
}

TEST(ContactsDouble, PairLinesAreTheDoubleContactsBitForBit) {
    scratch s;
    const std::vector<obbsat::rect_pose64> rows = utm_rows();
    write_file(s.file("poses.csv"), pose64_file(rows));
    std::string pair_text;
    std::vector<pair_index> pairs;
    for (std::uint32_t k = 0; k + 1 < rows.size(); ++k) {
        pairs.push_back({k, k + 1});
        pair_text += std::to_string(k) + "," + std::to_string(k + 1) + "\n";
    }
    write_file(s.file("pairs.csv"), pair_text);
    const auto r = s.run("contacts --poses poses.csv --pairs pairs.csv --margin 0.1 --precision double --threads 2");
    ASSERT_EQ(r.status, 0) << r.err;
    obbsat::contact_options64 options;
    options.margin = 0.1;
    const std::vector<obbsat::contact64> expected =
        obbsat::contact_pairs(obbsat::pose_records64(rows), pairs, options);
    const std::vector<std::string> lines = lines_of(r.out);
    std::size_t k = 0;
    for (const std::string& line : lines) {
        while (k < pairs.size() && expected[k].point_count == 0) {
            ++k;
        }
        ASSERT_LT(k, pairs.size()) << line;
        const obbsat::contact64& c = expected[k];
        const std::vector<std::string> f = fields_of(line);
        ASSERT_EQ(f.size(), 12u) << line;
        EXPECT_EQ(f[0] + "," + f[1], std::to_string(pairs[k].a) + "," + std::to_string(pairs[k].b));
        EXPECT_EQ(double_of(f[2]), c.nx) << line;
        EXPECT_EQ(double_of(f[3]), c.ny) << line;
        EXPECT_EQ(double_of(f[4]), c.depth) << line;
        EXPECT_EQ(f[5], std::to_string(c.point_count)) << line;
        for (std::uint32_t p = 0; p < c.point_count; ++p) {
            EXPECT_EQ(double_of(f[6 + 3 * p]), c.points[p].x) << line;
            EXPECT_EQ(double_of(f[7 + 3 * p]), c.points[p].y) << line;
            EXPECT_EQ(double_of(f[8 + 3 * p]), c.points[p].separation) << line;
        }
        ++k;
    }
    EXPECT_GT(lines.size(), 10u);
    // In float the same file gives other numbers: the double path reads and computes in double.
    const auto in_float = s.run("contacts --poses poses.csv --pairs pairs.csv --margin 0.1");
    EXPECT_NE(in_float.out, r.out);
}

TEST(ContactsDouble, CornerAndDistanceLinesAreTheDoubleValuesBitForBit) {
    scratch s;
    const obbsat::rect64 rects[] = {{{500000, 5000001}, {500002, 5000001}, {500002, 5000000}, {500000, 5000000}},
                                    {{500001, 5000002}, {500003, 5000002}, {500003, 5000000.5},
                                     {500001, 5000000.5}},
                                    {{500006.1, 5000001}, {500007, 5000001}, {500007, 5000000.3},
                                     {500006.1, 5000000.3}}};
    std::string text;
    char line[400];
    for (const obbsat::rect64& q : rects) {
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a,%a,%a\n", q.ul.x, q.ul.y, q.ur.x, q.ur.y, q.lr.x,
                      q.lr.y, q.ll.x, q.ll.y);
        text += line;
    }
    write_file(s.file("rects.csv"), text);
    write_file(s.file("pairs.csv"), "0,1\n0,2\n");
    const obbsat::rect_records64 store(rects, 3);
    const std::vector<pair_index> pairs = {{0, 1}, {0, 2}};

    const auto c = s.run("contacts --rects rects.csv --pairs pairs.csv --precision double");
    ASSERT_EQ(c.status, 0) << c.err;
    const obbsat::contact64 expected = obbsat::contact_pairs(store, pairs)[0];
    const std::vector<std::string> lines = lines_of(c.out);
    ASSERT_EQ(lines.size(), 1u);
    const std::vector<std::string> f = fields_of(lines[0]);
    EXPECT_EQ(double_of(f[4]), expected.depth);
    EXPECT_EQ(double_of(f[6]), expected.points[0].x);

    const auto d = s.run("distance --rects rects.csv --pairs pairs.csv --precision double");
    ASSERT_EQ(d.status, 0) << d.err;
    const std::vector<obbsat::closest_points64> distances = obbsat::distance_pairs(store, pairs);
    const std::vector<std::string> distance_lines = lines_of(d.out);
    ASSERT_EQ(distance_lines.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        const std::vector<std::string> g = fields_of(distance_lines[k]);
        ASSERT_EQ(g.size(), 7u);
        const obbsat::closest_points64& e = distances[k];
        const double values[] = {e.distance, e.ax, e.ay, e.bx, e.by};
        for (std::size_t v = 0; v < 5; ++v) {
            EXPECT_EQ(double_of(g[2 + v]), values[v]) << distance_lines[k];
        }
    }
    EXPECT_GT(distances[1].distance, 4.0);
}

/// Checks that `out` holds one line per pair of `expected`, in order, each
/// the pair and the double contact's fields bit for bit.
void expect_double_lines(const std::string& out, const obbsat::scene_contacts64& expected) {
    const std::vector<std::string> lines = lines_of(out);
    ASSERT_EQ(lines.size(), expected.pairs.size());
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const obbsat::contact64& c = expected.contacts[k];
        const std::vector<std::string> f = fields_of(lines[k]);
        ASSERT_EQ(f.size(), 12u) << lines[k];
        EXPECT_EQ(f[0] + "," + f[1], std::to_string(expected.pairs[k].a) + "," + std::to_string(expected.pairs[k].b));
        EXPECT_EQ(double_of(f[2]), c.nx) << lines[k];
        EXPECT_EQ(double_of(f[3]), c.ny) << lines[k];
        EXPECT_EQ(double_of(f[4]), c.depth) << lines[k];
        EXPECT_EQ(f[5], std::to_string(c.point_count)) << lines[k];
        for (std::uint32_t p = 0; p < c.point_count; ++p) {
            EXPECT_EQ(double_of(f[6 + 3 * p]), c.points[p].x) << lines[k];
            EXPECT_EQ(double_of(f[7 + 3 * p]), c.points[p].y) << lines[k];
            EXPECT_EQ(double_of(f[8 + 3 * p]), c.points[p].separation) << lines[k];
        }
    }
}

TEST(ContactsDouble, SceneLinesAreFindContacts64BitForBit) {
    // Without --pairs, --precision double writes every colliding pair of the
    // file (and with a margin every pair within it) with its double contact:
    // find_contacts64's answer on the double store, on every backend.
    scratch s;
    const std::vector<obbsat::rect_pose64> rows = utm_rows();
    write_file(s.file("poses.csv"), pose64_file(rows));
    const obbsat::pose_records64 store(rows);
    for (const double margin : {0.0, 0.1}) {
        SCOPED_TRACE("margin " + std::to_string(margin));
        obbsat::collide_options options;
        options.test = obbsat::method::exact;
        const obbsat::scene_contacts64 expected = obbsat::find_contacts64(store, options, margin);
        ASSERT_GT(expected.pairs.size(), 10u);
        const std::string base = "contacts --poses poses.csv --precision double --margin " + std::to_string(margin);
        const auto r = s.run(base + " --threads 2");
        ASSERT_EQ(r.status, 0) << r.err;
        expect_double_lines(r.out, expected);
        for (const obbsat::backend b : obbsat::compiled_backends()) {
            if (obbsat::cpu_supports(b)) {
                EXPECT_EQ(s.run(base + " --backend " + obbsat::backend_name(b)).out, r.out) << obbsat::backend_name(b);
            }
        }
        // In float the same file gives other numbers.
        EXPECT_NE(s.run("contacts --poses poses.csv --margin " + std::to_string(margin)).out, r.out);
    }
    // Another method on double poses.
    obbsat::collide_options local;
    local.test = obbsat::method::local;
    const auto r = s.run("contacts --poses poses.csv --precision double --method local");
    ASSERT_EQ(r.status, 0) << r.err;
    expect_double_lines(r.out, obbsat::find_contacts64(store, local));
    // A bad row is named with its file and line, and nothing is written.
    std::vector<obbsat::rect_pose64> bad = rows;
    bad[7].rotation = {0.0, 0.0};
    write_file(s.file("bad.csv"), pose64_file(bad));
    const auto refused = s.run("contacts --poses bad.csv --precision double");
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.err.find("bad.csv:8:"), std::string::npos) << refused.err;
    EXPECT_EQ(refused.out, "");
}

TEST(ContactsDouble, SceneOfDoubleCornersWithAHeader) {
    scratch s;
    std::vector<obbsat::rect64> rects;
    std::string text = "# double corners\n";
    char line[400];
    for (const obbsat::rect_pose64& p : utm_rows()) {
        const double ux = p.rotation.x * p.half_extents.x, uy = p.rotation.y * p.half_extents.x;
        const double vx = -p.rotation.y * p.half_extents.y, vy = p.rotation.x * p.half_extents.y;
        const obbsat::rect64 q{{p.center.x - ux + vx, p.center.y - uy + vy},
                               {p.center.x + ux + vx, p.center.y + uy + vy},
                               {p.center.x + ux - vx, p.center.y + uy - vy},
                               {p.center.x - ux - vx, p.center.y - uy - vy}};
        rects.push_back(q);
        std::snprintf(line, sizeof line, "%a,%a,%a,%a,%a,%a,%a,%a\n", q.ul.x, q.ul.y, q.ur.x, q.ur.y, q.lr.x,
                      q.lr.y, q.ll.x, q.ll.y);
        text += line;
    }
    write_file(s.file("rects.csv"), text);
    const auto r = s.run("contacts --rects rects.csv --precision double --margin 0.05 --header");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(r.out.rfind("i,j,nx,ny,depth,count,x1,y1,s1,x2,y2,s2\n", 0), 0u) << r.out;
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    const obbsat::scene_contacts64 expected = obbsat::find_contacts64(rects, options, 0.05);
    ASSERT_FALSE(expected.pairs.empty());
    expect_double_lines(r.out.substr(r.out.find('\n') + 1), expected);
}

TEST(ContactsDouble, UsageErrors) {
    scratch s;
    write_file(s.file("poses.csv"), "0,0,1,1,1,0\n1.5,0,1,1,1,0\n");
    write_file(s.file("pairs.csv"), "0,1\n");
    // A method that does not run on double poses is refused before the file is read.
    auto r = s.run("contacts --poses poses.csv --precision double --method sat4");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--precision double"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
    // Every backend this CPU runs gives the scalar backend's lines, in double too.
    for (const char* command : {"contacts", "distance"}) {
        const std::string base = std::string(command) + " --poses poses.csv --pairs pairs.csv --precision double";
        const auto scalar = s.run(base + " --backend scalar");
        EXPECT_EQ(scalar.status, 0) << scalar.err;
        for (const obbsat::backend b : obbsat::compiled_backends()) {
            if (obbsat::cpu_supports(b)) {
                r = s.run(base + " --backend " + obbsat::backend_name(b));
                EXPECT_EQ(r.status, 0) << r.err;
                EXPECT_EQ(r.out, scalar.out) << command << " on " << obbsat::backend_name(b);
            }
        }
    }
    r = s.run("contacts --poses poses.csv --pairs pairs.csv --precision quad");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--precision"), std::string::npos) << r.err;
    write_file(s.file("bad.csv"), "0,0,1,1,1,0\n1.5,0,1,1,0,0\n");
    r = s.run("contacts --poses bad.csv --pairs pairs.csv --precision double");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.csv:2:"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(ContactsErrors, NameTheFileAndLineAndWriteNothing) {
    scratch s;
    write_file(s.file("poses.csv"), "0,0,1,1,1,0\n1.5,0,1,1,1,0\n");
    write_file(s.file("pairs.csv"), "0,1\n\n1,2\n");
    write_file(s.file("rects.csv"), "# quads\n0,1,2,1,2,0,0,0\n0,0,1,1,2,2,3,3\n");
    write_file(s.file("one.csv"), "0,1\n");
    const std::vector<std::string> before = s.entries();

    auto r = s.run("contacts --poses poses.csv --pairs pairs.csv --out c.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("pairs.csv:3:"), std::string::npos) << r.err;
    r = s.run("distance --poses poses.csv --pairs pairs.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("pairs.csv:3:"), std::string::npos) << r.err;
    // A quad that is not strictly convex, found by the library after reading: its line.
    r = s.run("contacts --rects rects.csv --pairs one.csv --out c.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("rects.csv:3: rectangle 1:"), std::string::npos) << r.err;
    r = s.run("contacts --rects rects.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("rects.csv:3: rectangle 1:"), std::string::npos) << r.err;
    r = s.run("distance --rects rects.csv --pairs one.csv --out d.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("rects.csv:3:"), std::string::npos) << r.err;
    for (const char* margin : {"-1", "nan", "inf", "x"}) {
        r = s.run(std::string("contacts --poses poses.csv --out c.csv --margin ") + margin);
        EXPECT_EQ(r.status, 2) << margin;
        EXPECT_NE(r.err.find("--margin"), std::string::npos) << r.err;
    }
    r = s.run("distance --poses poses.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--pairs"), std::string::npos) << r.err;
    // A method that does not run on the store, an unknown one, one beside a list.
    for (const char* method : {"sat4", "no_such_method"}) {
        r = s.run(std::string("contacts --poses poses.csv --out c.csv --method ") + method);
        EXPECT_EQ(r.status, 2) << method;
        EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
    }
    r = s.run("contacts --poses poses.csv --pairs one.csv --method local --out c.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
    EXPECT_EQ(s.entries(), before);  // no output file, no temporary left behind
}

TEST(ContactsErrors, AnExistingOutputFileIsKeptOnError) {
    scratch s;
    write_file(s.file("poses.csv"), "0,0,1,1,1,0\n1.5,0,1,1,1,0\n");
    write_file(s.file("pairs.csv"), "0,5\n");
    write_file(s.file("c.csv"), "old\n");
    const auto r = s.run("contacts --poses poses.csv --pairs pairs.csv --out c.csv");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(read_file(s.file("c.csv")), "old\n");
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++count;
    }
    return count;
}

TEST(DrawContacts, AColliderShowsItsNormalAndPointsAndAnApartPairNone) {
    scratch s;
    write_file(s.file("poses.csv"), "0,0,1,0.5,1,0\n1.5,0.3,1,1,0.8,0.6\n5,5,1,1,1,0\n");
    write_file(s.file("rects.csv"), "0,1,2,1,2,0,0,0\n1,2,3,2,3,0.5,1,0.5\n");
    write_file(s.file("pairs.csv"), "0,1\n0,2\n");
    auto r = s.run("draw --poses poses.csv --pairs pairs.csv --select 0,1 --out p.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string svg = read_file(s.file("p.svg"));
    EXPECT_EQ(count_of(svg, "class=\"contact-overlay\""), 1u);  // only the colliding pair 0
    EXPECT_EQ(count_of(svg, "class=\"contact-normal\""), 1u);
    EXPECT_EQ(count_of(svg, "class=\"contact-point\""), 2u);
    // The normal (0.8, 0.6) from A to B: rightwards and, as SVG's y grows downwards, upwards.
    const std::size_t line = svg.find("class=\"contact-normal\"");
    const auto value_after = [&](const std::string& name) {
        const std::size_t at = svg.find(name + "=\"", line) + name.size() + 2;
        return std::strtod(svg.c_str() + at, nullptr);
    };
    EXPECT_GT(value_after("x2"), value_after("x1"));
    EXPECT_LT(value_after("y2"), value_after("y1"));

    write_file(s.file("one.csv"), "0,1\n");
    r = s.run("draw --rects rects.csv --pairs one.csv --select 0 --out r.svg");
    ASSERT_EQ(r.status, 0) << r.err;
    svg = read_file(s.file("r.svg"));
    EXPECT_EQ(count_of(svg, "class=\"contact-overlay\""), 1u);
    EXPECT_GE(count_of(svg, "class=\"contact-point\""), 1u);
}

}  // namespace
