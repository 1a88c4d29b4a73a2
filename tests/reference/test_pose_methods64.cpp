// The references of the methods on double poses (obbsat/ref/local64.hpp,
// pose_conservative64.hpp, pose_exact64.hpp) against the exact double pose
// oracle (itself checked against GMP in tests/oracle) on the families of
// test_support/pose_cases64.hpp: exact must agree on every pair, conservative
// must never miss a collision, and the certified path's claims must all hold.
#include "test_support/pose_cases64.hpp"

#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>
#include <obbsat/ref/pose_exact64.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

using obbsat::rect_pose64;
using obbsat::test::pose_pair64;

std::string show(const rect_pose64& p) {
    char text[240];
    std::snprintf(text, sizeof text, "{c %a,%a h %a,%a r %a,%a}", p.center.x, p.center.y, p.half_extents.x,
                  p.half_extents.y, p.rotation.x, p.rotation.y);
    return text;
}

std::string show(const pose_pair64& pair) { return "A " + show(pair.a) + "\nB " + show(pair.b); }

// The pose rounded to float32, as obbsat's float stores would hold it.
obbsat::rect_pose rounded_to_float(const rect_pose64& p) {
    auto f = [](double v) { return static_cast<float>(v); };
    return obbsat::rect_pose{{f(p.center.x), f(p.center.y)},
                             {f(p.half_extents.x), f(p.half_extents.y)},
                             {f(p.rotation.x), f(p.rotation.y)}};
}

struct tally {
    int pairs = 0;
    int intersecting = 0;
    int slow_path = 0;               // pairs the certified path left to the oracle
    int conservative_false_hits = 0; // separated pairs conservative calls colliding
    int local_wrong = 0;
    int float32_wrong = 0;           // the exact answer for the poses rounded to float32
};

// Fills `t`; a void function, so that a failed assertion stops at the first bad pair.
void check_family(const char* name, std::uint64_t seed, int count, pose_pair64 (*make)(obbsat::seeded_random&),
                  tally& t) {
    obbsat::seeded_random random(seed);
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const pose_pair64 pair = make(random);
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
        t.slow_path += !fast.separated && !fast.intersecting ? 1 : 0;

        const bool conservative = obbsat::ref::conservative(pair.a, pair.b);
        if (truth) {
            ASSERT_TRUE(conservative) << "conservative missed a collision\n" << show(pair);
        }
        t.conservative_false_hits += conservative && !truth ? 1 : 0;

        const bool local = obbsat::ref::local(pair.a, pair.b);
        if (local != truth) {
            // local errs only where the certified path cannot decide either.
            ASSERT_FALSE(fast.separated || fast.intersecting) << "local wrong on a certified pair\n" << show(pair);
            ++t.local_wrong;
        }
        const obbsat::rect_pose fa = rounded_to_float(pair.a);
        const obbsat::rect_pose fb = rounded_to_float(pair.b);
        if (obbsat::oracle::pose_defect(fa) == nullptr && obbsat::oracle::pose_defect(fb) == nullptr) {
            t.float32_wrong += obbsat::oracle::intersects(fa, fb) != truth ? 1 : 0;
        }
    }
    std::printf("[ double   ] %-26s %7d pairs  hit %7d  slow path %6d  conservative false hits %6d  "
                "local wrong %5d  float32 wrong %6d\n",
                name, t.pairs, t.intersecting, t.slow_path, t.conservative_false_hits, t.local_wrong,
                t.float32_wrong);
}

TEST(pose_methods64, utm_random_pairs) {
    tally t;
    check_family("UTM random", 31, 1000000, obbsat::test::utm_random_pair, t);
    EXPECT_GT(t.intersecting, 100000);
    // Nothing near contact: the fast path decides nearly every pair, and
    // conservative is exact on them.
    EXPECT_LT(t.slow_path, t.pairs / 1000);
}

TEST(pose_methods64, utm_contacts_exact_and_nudged) {
    tally t;
    check_family("UTM contacts 500000.125", 32, 300000, obbsat::test::utm_contact_pair, t);
    EXPECT_GT(t.slow_path, 10000);  // exact contacts: only the oracle decides them
    // Rounded to float32 (spacing 0.03125 m at 5e5), millimetre and ulp gaps vanish.
    EXPECT_GT(t.float32_wrong, 1000);
}

TEST(pose_methods64, utm_northing_contacts) {
    tally t;
    check_family("UTM contacts 6e6", 33, 300000, obbsat::test::utm_northing_contact_pair, t);
    EXPECT_GT(t.float32_wrong, 1000);
}

TEST(pose_methods64, far_contacts) { tally t;
    check_family("contacts 1e9..1e15", 34, 300000, obbsat::test::far_contact_pair, t); }

TEST(pose_methods64, far_random_pairs) {
    tally t;
    check_family("random 1e9..1e15", 35, 300000, obbsat::test::far_random_pair, t);
}

TEST(pose_methods64, slivers) { tally t;
    check_family("slivers", 36, 300000, obbsat::test::sliver_pair, t); }

TEST(pose_methods64, near_parallel_pairs) {
    tally t;
    check_family("near parallel", 37, 300000, obbsat::test::near_parallel_pair, t);
}

TEST(pose_methods64, rotation_lengths_from_1e_60_to_1e60) {
    tally t;
    check_family("scaled rotations", 38, 300000, obbsat::test::scaled_rotation_pair, t);
}

// Two 20 m x 10 m footprints side by side at UTM easting 500000.125: touching
// exactly, a millimetre apart, and a millimetre into each other. float32 holds
// all three as the same poses.
TEST(pose_methods64, footprints_a_millimetre_apart) {
    const rect_pose64 a{{500000.125, 5712345.5}, {10.0, 5.0}, {1.0, 0.0}};
    rect_pose64 touching{{500020.125, 5712345.5}, {10.0, 5.0}, {1.0, 0.0}};
    rect_pose64 apart = touching;
    apart.center.x += 0.001;
    rect_pose64 into = touching;
    into.center.x -= 0.001;
    EXPECT_TRUE(obbsat::ref::exact(a, touching));
    EXPECT_FALSE(obbsat::ref::exact(a, apart));
    EXPECT_TRUE(obbsat::ref::exact(a, into));
    EXPECT_TRUE(obbsat::ref::conservative(a, touching));
    EXPECT_TRUE(obbsat::ref::conservative(a, into));
    EXPECT_FALSE(obbsat::ref::conservative(a, apart));  // a millimetre is far above its margin
    EXPECT_FALSE(obbsat::ref::local(a, apart));
    EXPECT_EQ(obbsat::oracle::classify(a, touching), obbsat::oracle::contact::touching);
    // The same three in float32: the millimetre is gone.
    EXPECT_EQ(rounded_to_float(apart).center.x, rounded_to_float(touching).center.x);
    EXPECT_EQ(rounded_to_float(into).center.x, rounded_to_float(touching).center.x);
}

// The same footprints turned by a rotation vector (3, 4)/8 (not unit: the
// rectangle is scaled by 5/8, exactly), touching, and one ulp of 500000 apart.
// The center difference is exact, so the fast path's margin is relative to the
// pair's own size, not to 500000: it proves the ulp gap, and only the exact
// contact goes to the oracle.
TEST(pose_methods64, footprints_one_ulp_apart_turned) {
    const obbsat::point64 r{0.375, 0.5};
    const rect_pose64 a{{500000.125, 5712345.5}, {16.0, 8.0}, r};
    // B's center at A's center + (16 + 16)·(c, s): edge to edge along A's u.
    const rect_pose64 touching{{500000.125 + 32.0 * 0.375, 5712345.5 + 32.0 * 0.5}, {16.0, 8.0}, r};
    rect_pose64 apart = touching;
    apart.center.x = std::nextafter(apart.center.x, INFINITY);
    apart.center.y = std::nextafter(apart.center.y, INFINITY);
    EXPECT_TRUE(obbsat::ref::exact(a, touching));
    EXPECT_FALSE(obbsat::ref::exact(a, apart));
    EXPECT_TRUE(obbsat::ref::conservative(a, touching));
    EXPECT_FALSE(obbsat::ref::conservative(a, apart));
    const obbsat::ref::certified_verdict at_contact = obbsat::ref::certify(a, touching);
    EXPECT_FALSE(at_contact.separated || at_contact.intersecting);  // left to the oracle
    EXPECT_TRUE(obbsat::ref::certify(a, apart).separated);
    // float32 holds the two B's as one pose.
    EXPECT_EQ(rounded_to_float(apart).center.x, rounded_to_float(touching).center.x);
}

TEST(pose_methods64, out_of_range_proves_nothing) {
    // Rotations beyond [2^-500, 2^500]: margins are infinite, the oracle decides.
    const rect_pose64 a{{0, 0}, {1, 1}, {0x1p-600, 0}};
    const rect_pose64 b{{0x1p-600, 0}, {1, 1}, {0x1p-600, 0}};
    const obbsat::ref::pose_margins64 m = obbsat::ref::margins_of(a, b, obbsat::ref::local_axes(a, b));
    EXPECT_EQ(m.a, INFINITY);
    EXPECT_EQ(m.b, INFINITY);
    EXPECT_TRUE(obbsat::ref::exact(a, b));
    EXPECT_TRUE(obbsat::ref::conservative(a, b));
    // Centers 1e308 apart: the difference overflows, nothing is claimed, the oracle answers.
    const rect_pose64 far_left{{-1e308, 0}, {1, 1}, {1, 0}};
    const rect_pose64 far_right{{1e308, 0}, {1, 1}, {1, 0}};
    EXPECT_FALSE(obbsat::ref::exact(far_left, far_right));
    EXPECT_TRUE(obbsat::ref::conservative(far_left, far_right));
}

}  // namespace
