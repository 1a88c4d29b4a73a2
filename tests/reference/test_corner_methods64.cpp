// The references of the methods on double corners (obbsat/ref/certified64.hpp,
// conservative64.hpp, exact64.hpp) against the exact double corner oracle
// (checked against GMP in tests/oracle) on the corners of the families of
// test_support/pose_cases64.hpp: exact must agree on every pair, conservative
// must never miss a collision, and no certified claim may contradict the oracle.
#include "test_support/pose_cases64.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/contact64.hpp>
#include <obbsat/ref/certified64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/exact64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

using obbsat::point64;
using obbsat::rect64;
using obbsat::test::corner_pair;
using obbsat::test::rect_pair64;

std::string show(const rect_pair64& pair) {
    char text[600];
    const rect64& a = pair.a;
    const rect64& b = pair.b;
    std::snprintf(text, sizeof text, "A {%a,%a %a,%a %a,%a %a,%a}\nB {%a,%a %a,%a %a,%a %a,%a}", a.ul.x, a.ul.y,
                  a.ur.x, a.ur.y, a.lr.x, a.lr.y, a.ll.x, a.ll.y, b.ul.x, b.ul.y, b.ur.x, b.ur.y, b.lr.x, b.lr.y,
                  b.ll.x, b.ll.y);
    return text;
}

obbsat::rect rounded_to_float(const rect64& r) {
    auto f = [](point64 p) { return obbsat::point{static_cast<float>(p.x), static_cast<float>(p.y)}; };
    return obbsat::rect{f(r.ul), f(r.ur), f(r.lr), f(r.ll)};
}

struct tally {
    int pairs = 0;
    int intersecting = 0;
    int slow_path = 0;
    int slow_path_with_area = 0;  // of those, pairs of two quads with area (not a point or a segment)
    int conservative_false_hits = 0;
    int float32_wrong = 0;
};

void check_family(const char* name, std::uint64_t seed, int count, rect_pair64 (*make)(obbsat::seeded_random&),
                  tally& t) {
    obbsat::seeded_random random(seed);
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const rect_pair64 pair = make(random);
        const bool truth = obbsat::oracle::intersects(pair.a, pair.b);
        ++t.pairs;
        t.intersecting += truth ? 1 : 0;
        ASSERT_EQ(obbsat::ref::exact(pair.a, pair.b), truth) << show(pair);
        ASSERT_EQ(obbsat::ref::exact(pair.b, pair.a), truth) << "swapped\n" << show(pair);
        const obbsat::ref::certified_verdict fast = obbsat::ref::certify(pair.a, pair.b);
        ASSERT_FALSE(fast.separated && fast.intersecting) << show(pair);
        if (fast.separated) {
            ASSERT_FALSE(truth) << "certified separated\n" << show(pair);
        }
        if (fast.intersecting) {
            ASSERT_TRUE(truth) << "certified intersecting\n" << show(pair);
        }
        if (!fast.separated && !fast.intersecting) {
            ++t.slow_path;
            auto has_area = [](const rect64& r) {
                const obbsat::oracle::quad_form form = obbsat::oracle::region_of(r).form;
                return form != obbsat::oracle::quad_form::point && form != obbsat::oracle::quad_form::segment;
            };
            t.slow_path_with_area += has_area(pair.a) && has_area(pair.b) ? 1 : 0;
        }
        const bool conservative = obbsat::ref::conservative(pair.a, pair.b);
        if (truth) {
            ASSERT_TRUE(conservative) << "conservative missed a collision\n" << show(pair);
        }
        t.conservative_false_hits += conservative && !truth ? 1 : 0;
        t.float32_wrong += obbsat::oracle::intersects(rounded_to_float(pair.a), rounded_to_float(pair.b)) != truth;
    }
    std::printf("[ corners64] %-26s %7d pairs  hit %7d  slow path %6d (with area %6d)  conservative false hits "
                "%6d  float32 wrong %6d\n",
                name, t.pairs, t.intersecting, t.slow_path, t.slow_path_with_area, t.conservative_false_hits,
                t.float32_wrong);
}

TEST(corner_methods64, utm_random_pairs) {
    tally t;
    check_family("UTM random", 61, 500000, corner_pair<obbsat::test::utm_random_pair>, t);
    EXPECT_GT(t.intersecting, 50000);
    // Only quads without area (a zero half extent: about 23 % of these pairs) go
    // to the oracle, the fast path proves nothing about them; of the others, none.
    EXPECT_GT(t.slow_path, t.pairs / 10);
    EXPECT_LT(t.slow_path_with_area, t.pairs / 1000);
}

TEST(corner_methods64, utm_contacts) {
    tally t;
    check_family("UTM contacts 500000.125", 62, 200000, corner_pair<obbsat::test::utm_contact_pair>, t);
    EXPECT_GT(t.slow_path, 10000);
    EXPECT_GT(t.float32_wrong, 1000);
    tally north;
    check_family("UTM contacts 6e6", 63, 200000, corner_pair<obbsat::test::utm_northing_contact_pair>, north);
}

TEST(corner_methods64, far_pairs) {
    tally contacts;
    check_family("contacts 1e9..1e15", 64, 200000, corner_pair<obbsat::test::far_contact_pair>, contacts);
    tally random_pairs;
    check_family("random 1e9..1e15", 65, 200000, corner_pair<obbsat::test::far_random_pair>, random_pairs);
}

TEST(corner_methods64, slivers_and_near_parallel_pairs) {
    tally slivers;
    check_family("slivers", 66, 200000, corner_pair<obbsat::test::sliver_pair>, slivers);
    tally parallel;
    check_family("near parallel", 67, 200000, corner_pair<obbsat::test::near_parallel_pair>, parallel);
}

TEST(corner_methods64, corners_moved_by_ulps) {
    tally t;
    check_family("corners moved by ulps", 68, 200000, obbsat::test::nudged_corner_pair, t);
}

TEST(corner_methods64, rotation_lengths_far_from_unit) {
    tally t;
    check_family("scaled rotations", 69, 200000, corner_pair<obbsat::test::scaled_rotation_pair>, t);
}

// Two axis-aligned 20 m x 10 m footprints at UTM easting 500000.125: touching,
// a millimetre apart, a millimetre into each other.
TEST(corner_methods64, footprints_a_millimetre_apart) {
    auto footprint = [](double west) {
        return rect64{{west, 5712350.5}, {west + 20.0, 5712350.5}, {west + 20.0, 5712340.5}, {west, 5712340.5}};
    };
    const rect64 a = footprint(500000.125);
    const rect64 touching = footprint(500020.125);
    const rect64 apart = footprint(500020.126);
    const rect64 into = footprint(500020.124);
    EXPECT_TRUE(obbsat::ref::exact(a, touching));
    EXPECT_FALSE(obbsat::ref::exact(a, apart));
    EXPECT_TRUE(obbsat::ref::exact(a, into));
    EXPECT_TRUE(obbsat::ref::conservative(a, touching));
    EXPECT_FALSE(obbsat::ref::conservative(a, apart));
    EXPECT_TRUE(obbsat::ref::certify(a, apart).separated);
    EXPECT_TRUE(obbsat::ref::certify(a, into).intersecting);
    const obbsat::ref::certified_verdict contact = obbsat::ref::certify(a, touching);
    EXPECT_FALSE(contact.separated || contact.intersecting);
    EXPECT_EQ(obbsat::oracle::classify(a, touching), obbsat::oracle::contact::touching);
    // float32 cannot tell the three apart: 500020.125 ± 0.001 rounds to 500020.125.
    EXPECT_EQ(rounded_to_float(apart).ul.x, rounded_to_float(touching).ul.x);
    EXPECT_EQ(rounded_to_float(into).ul.x, rounded_to_float(touching).ul.x);
}

TEST(corner_methods64, out_of_range_proves_nothing) {
    // Coordinates near 1e308: widths overflow, the guards leave everything to the oracle.
    const rect64 a{{-1e308, 1}, {-0.9e308, 1}, {-0.9e308, 0}, {-1e308, 0}};
    const rect64 b{{0.9e308, 1}, {1e308, 1}, {1e308, 0}, {0.9e308, 0}};
    const obbsat::ref::certified_verdict fast = obbsat::ref::certify(a, b);
    EXPECT_FALSE(fast.separated || fast.intersecting);
    EXPECT_TRUE(obbsat::ref::conservative(a, b));
    EXPECT_FALSE(obbsat::ref::exact(a, b));
}

}  // namespace
