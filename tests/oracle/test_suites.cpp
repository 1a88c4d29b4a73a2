// The hard-case suites: exact sizes, valid indices, determinism, a real share
// of pairs on or near a contact boundary in every family (judged by the exact
// oracle), and the constructions that promise an exact answer: grazing gaps
// of k float steps, integer rectangles that touch, tile maps that share edges.
#include <obbsat/error.hpp>
#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/suites/boundary.hpp>
#include <obbsat/suites/suite.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace {

using obbsat::rect;
using obbsat::oracle::contact;
using obbsat::suites::family;
using obbsat::suites::suite;

std::string name_of(const ::testing::TestParamInfo<family>& info) {
    return obbsat::suites::family_name(info.param);
}

bool same_bytes(const suite& x, const suite& y) {
    return x.rects.size() == y.rects.size() && x.pairs.size() == y.pairs.size() &&
           x.tags == y.tags && x.tag_names == y.tag_names &&
           std::memcmp(x.rects.data(), y.rects.data(), x.rects.size() * sizeof(rect)) == 0 &&
           std::memcmp(x.pairs.data(), y.pairs.data(), x.pairs.size() * sizeof(obbsat::pair_index)) == 0;
}

TEST(suite_family, names_round_trip_and_unknown_names_are_rejected) {
    EXPECT_EQ(obbsat::suites::all_families().size(), 11u);
    for (const family f : obbsat::suites::all_families()) {
        EXPECT_EQ(obbsat::suites::parse_family(obbsat::suites::family_name(f)), f);
    }
    try {
        obbsat::suites::parse_family("nearparallel");
        FAIL() << "expected obbsat::invalid_input";
    } catch (const obbsat::invalid_input& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("nearparallel"), std::string::npos) << message;
        EXPECT_NE(message.find("near_parallel"), std::string::npos) << message;
    }
}

class suite_of : public ::testing::TestWithParam<family> {};

TEST_P(suite_of, has_exactly_the_pairs_asked_for_with_valid_indices_and_tags) {
    for (const std::size_t wanted : {0u, 1u, 7u, 1000u}) {
        const suite s = obbsat::suites::make_family(GetParam(), 3, wanted);
        ASSERT_EQ(s.pairs.size(), wanted);
        ASSERT_EQ(s.tags.size(), wanted);
        EXPECT_EQ(s.source, GetParam());
        for (std::size_t i = 0; i < wanted; ++i) {
            ASSERT_LT(s.pairs[i].a, s.rects.size());
            ASSERT_LT(s.pairs[i].b, s.rects.size());
            ASSERT_LT(s.tags[i], s.tag_names.size());
        }
        for (const rect& r : s.rects) {
            const float v[8] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
            for (const float x : v) {
                ASSERT_TRUE(std::isfinite(x));
            }
        }
    }
}

TEST_P(suite_of, is_deterministic_in_its_seed) {
    const suite first = obbsat::suites::make_family(GetParam(), 42, 3000);
    const suite again = obbsat::suites::make_family(GetParam(), 42, 3000);
    const suite other = obbsat::suites::make_family(GetParam(), 43, 3000);
    EXPECT_TRUE(same_bytes(first, again));
    EXPECT_FALSE(same_bytes(first, other));
}

TEST_P(suite_of, puts_a_real_share_of_pairs_on_or_near_a_contact_boundary) {
    // Near: touching, or a move of the second rect by 1..4 float steps along an
    // axis changes the class. Every family is built for this; a tenth is the floor.
    const suite s = obbsat::suites::make_family(GetParam(), 5, 4000);
    std::size_t near = 0;
    std::size_t touching = 0;
    for (std::size_t i = 0; i < s.pairs.size(); ++i) {
        const rect& a = s.rects[s.pairs[i].a];
        const rect& b = s.rects[s.pairs[i].b];
        touching += obbsat::oracle::classify(a, b) == contact::touching;
        near += obbsat::suites::near_contact_boundary(a, b, 4);
    }
    std::printf("[ boundary ] %-17s touching %5zu  near (4 steps) %5zu of %zu\n",
                obbsat::suites::family_name(GetParam()), touching, near, s.pairs.size());
    EXPECT_GE(near * 10, s.pairs.size());
}

INSTANTIATE_TEST_SUITE_P(families, suite_of, ::testing::ValuesIn(obbsat::suites::all_families()),
                         name_of);

// Floats in an order-preserving integer line: the distance is the number of
// float steps between two values.
std::int64_t float_line(float v) {
    std::int32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits < 0 ? -static_cast<std::int64_t>(bits & 0x7fffffff) : bits;
}

float lowest(const rect& r, int axis) {
    const float v[4] = {axis == 0 ? r.ul.x : r.ul.y, axis == 0 ? r.ur.x : r.ur.y,
                        axis == 0 ? r.lr.x : r.lr.y, axis == 0 ? r.ll.x : r.ll.y};
    return std::fmin(std::fmin(v[0], v[1]), std::fmin(v[2], v[3]));
}

float highest(const rect& r, int axis) {
    const float v[4] = {axis == 0 ? r.ul.x : r.ul.y, axis == 0 ? r.ur.x : r.ur.y,
                        axis == 0 ? r.lr.x : r.lr.y, axis == 0 ? r.ll.x : r.ll.y};
    return std::fmax(std::fmax(v[0], v[1]), std::fmax(v[2], v[3]));
}

TEST(grazing, the_gap_is_exactly_the_tagged_number_of_float_steps_and_decides_the_class) {
    const suite s = obbsat::suites::make_family(family::grazing, 8, 5000);
    const std::vector<contact> classes = obbsat::oracle::classify_pairs(s.rects, s.pairs);
    int seen[9] = {};
    for (std::size_t i = 0; i < s.pairs.size(); ++i) {
        const std::string& tag = s.tag_of(i);
        const std::size_t colon = tag.find(':');
        ASSERT_NE(colon, std::string::npos) << tag;
        const std::string side = tag.substr(0, colon);
        const int k = std::stoi(tag.substr(colon + 1));
        ASSERT_GE(k, -4);
        ASSERT_LE(k, 4);
        ++seen[k + 4];
        const rect& box = s.rects[s.pairs[i].a];
        const rect& other = s.rects[s.pairs[i].b];
        // A is an axis-aligned box (its first edge horizontal, or vertical once transposed).
        const bool first_edge_horizontal = box.ul.y == box.ur.y && box.ur.x == box.lr.x &&
                                           box.lr.y == box.ll.y && box.ll.x == box.ul.x;
        const bool first_edge_vertical = box.ul.x == box.ur.x && box.ur.y == box.lr.y &&
                                         box.lr.x == box.ll.x && box.ll.y == box.ul.y;
        ASSERT_TRUE(first_edge_horizontal || first_edge_vertical) << tag;
        // Steps from A's edge line outwards to the other rect's nearest extreme.
        std::int64_t steps = 0;
        if (side == "right") {
            steps = float_line(lowest(other, 0)) - float_line(highest(box, 0));
        } else if (side == "left") {
            steps = float_line(lowest(box, 0)) - float_line(highest(other, 0));
        } else if (side == "top") {
            steps = float_line(lowest(other, 1)) - float_line(highest(box, 1));
        } else {
            ASSERT_EQ(side, "bottom");
            steps = float_line(lowest(box, 1)) - float_line(highest(other, 1));
        }
        ASSERT_EQ(steps, k) << tag << " pair " << i;
        const contact want = k > 0 ? contact::separated : (k == 0 ? contact::touching : contact::overlapping);
        ASSERT_EQ(classes[i], want) << tag << " pair " << i;
    }
    for (int k = -4; k <= 4; ++k) {
        EXPECT_GT(seen[k + 4], 300) << "gap " << k;
    }
}

TEST(integer_touching, every_unshifted_pair_touches_and_shifts_reach_every_class) {
    const suite s = obbsat::suites::make_family(family::integer_touching, 8, 5000);
    const std::vector<contact> classes = obbsat::oracle::classify_pairs(s.rects, s.pairs);
    int shifted[3] = {};
    for (std::size_t i = 0; i < s.pairs.size(); ++i) {
        const std::string& tag = s.tag_of(i);
        if (tag.size() > 6 && tag.compare(tag.size() - 6, 6, ":touch") == 0) {
            ASSERT_EQ(classes[i], contact::touching) << tag << " pair " << i;
        } else {
            ++shifted[static_cast<int>(classes[i])];
        }
    }
    EXPECT_GT(shifted[0], 100);
    EXPECT_GT(shifted[1], 100);
    EXPECT_GT(shifted[2], 100);
}

TEST(tiles, maps_with_shared_edges_never_overlap) {
    // Grid maps share every edge exactly, and axis-aligned brick bonds put
    // their T-junction corners exactly on the edge: only rotated brick bonds
    // may overlap, by rounding.
    const suite s = obbsat::suites::make_family(family::tiles, 8, 20000);
    const std::vector<contact> classes = obbsat::oracle::classify_pairs(s.rects, s.pairs);
    std::size_t touching = 0;
    for (std::size_t i = 0; i < s.pairs.size(); ++i) {
        const std::string& tag = s.tag_of(i);
        const bool may_overlap = tag.rfind("rot_", 0) == 0 && tag.find("brick") != std::string::npos;
        if (!may_overlap) {
            ASSERT_NE(classes[i], contact::overlapping) << tag << " pair " << i;
        }
        touching += classes[i] == contact::touching;
    }
    EXPECT_GT(touching * 5, s.pairs.size());
}

TEST(boundary, nudge_moves_by_whole_float_steps) {
    const rect r{{1, 2}, {3, 2}, {3, 0}, {1, 0}};
    const rect moved = obbsat::suites::nudge(r, 2, -1);
    EXPECT_EQ(moved.ul.x, std::nextafter(std::nextafter(1.0f, 2.0f), 2.0f));
    EXPECT_EQ(moved.ul.y, std::nextafter(2.0f, 0.0f));
    EXPECT_EQ(moved.ll.y, -std::numeric_limits<float>::denorm_min());
    const rect a{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const rect apart{{2, 1}, {3, 1}, {3, 0}, {2, 0}};
    const rect just_apart{{std::nextafter(1.0f, 2.0f), 1}, {2, 1}, {2, 0}, {std::nextafter(1.0f, 2.0f), 0}};
    EXPECT_FALSE(obbsat::suites::near_contact_boundary(a, apart, 4));
    EXPECT_TRUE(obbsat::suites::near_contact_boundary(a, just_apart, 1));
}

}  // namespace
