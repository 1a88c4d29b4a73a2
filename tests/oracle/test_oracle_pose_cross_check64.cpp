// The double pose oracle against an independent construction in GMP rationals:
// the four true corners of each pose, C ± hx·(c, s) ± hy·(−s, c), computed
// exactly from the stored doubles, and the two quads they bound compared by
// rational_model.hpp (segment intersection, ray-crossing containment, the area
// of the clipped intersection). The pairs come from every make of
// test_support/pose_cases64.hpp. Any difference fails with the pair in hex.
#include "rational_model.hpp"

#include "test_support/pose_cases64.hpp"

#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

namespace {

using obbsat::rect_pose64;
using obbsat::test::pose_pair64;
using obbsat::test::rational_point;

std::string show(const rect_pose64& p) {
    char text[240];
    std::snprintf(text, sizeof text, "{c %a,%a h %a,%a r %a,%a}", p.center.x, p.center.y, p.half_extents.x,
                  p.half_extents.y, p.rotation.x, p.rotation.y);
    return text;
}

obbsat::test::rational_corners true_corners(const rect_pose64& p) {
    const mpq_class cx(p.center.x), cy(p.center.y);
    const mpq_class hx(p.half_extents.x), hy(p.half_extents.y);
    const mpq_class c(p.rotation.x), s(p.rotation.y);
    const mpq_class ux = hx * c, uy = hx * s;   // hx·(c, s)
    const mpq_class vx = -hy * s, vy = hy * c;  // hy·(−s, c)
    return {rational_point{cx - ux + vx, cy - uy + vy}, rational_point{cx + ux + vx, cy + uy + vy},
            rational_point{cx + ux - vx, cy + uy - vy}, rational_point{cx - ux - vx, cy - uy - vy}};
}

char model_contact(const rect_pose64& a, const rect_pose64& b) {
    return obbsat::test::rational_contact(obbsat::test::rational_region_of(true_corners(a)),
                                          obbsat::test::rational_region_of(true_corners(b)));
}

std::map<char, int> cross_check(const char* name, std::uint64_t seed, int count,
                                pose_pair64 (*make)(obbsat::seeded_random&)) {
    obbsat::seeded_random random(seed);
    std::map<char, int> classes;
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const pose_pair64 pair = make(random);
        const char model = model_contact(pair.a, pair.b);
        const char oracle = obbsat::oracle::contact_letter(obbsat::oracle::classify(pair.a, pair.b));
        EXPECT_EQ(oracle, model) << "A " << show(pair.a) << "\nB " << show(pair.b);
        EXPECT_EQ(obbsat::oracle::contact_letter(obbsat::oracle::classify(pair.b, pair.a)), model)
            << "swapped: A " << show(pair.a) << "\nB " << show(pair.b);
        ++classes[model];
    }
    std::printf("[ model64  ] %-28s %6d pairs  S %6d  T %6d  O %6d\n", name, count, classes['S'], classes['T'],
                classes['O']);
    return classes;
}

TEST(pose_cross_check64, utm_random_pairs) {
    auto classes = cross_check("UTM random", 21, 20000, obbsat::test::utm_random_pair);
    EXPECT_GT(classes['S'], 2000);
    EXPECT_GT(classes['O'], 2000);
}

TEST(pose_cross_check64, utm_contacts_exact_and_nudged) {
    auto classes = cross_check("UTM contacts 500000.125", 22, 20000, obbsat::test::utm_contact_pair);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 1000) << c;
    }
}

TEST(pose_cross_check64, utm_northing_contacts) {
    auto classes = cross_check("UTM contacts 6e6", 23, 20000, obbsat::test::utm_northing_contact_pair);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 1000) << c;
    }
}

TEST(pose_cross_check64, far_contacts) {
    auto classes = cross_check("contacts 1e9..1e15", 24, 20000, obbsat::test::far_contact_pair);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 1000) << c;
    }
}

TEST(pose_cross_check64, far_random_pairs) {
    auto classes = cross_check("random 1e9..1e15", 25, 10000, obbsat::test::far_random_pair);
    EXPECT_GT(classes['S'], 1000);
    EXPECT_GT(classes['O'], 1000);
}

TEST(pose_cross_check64, slivers) {
    auto classes = cross_check("slivers", 26, 20000, obbsat::test::sliver_pair);
    EXPECT_GT(classes['S'], 1000);
    EXPECT_GT(classes['T'], 1000);
}

TEST(pose_cross_check64, near_parallel_pairs) {
    auto classes = cross_check("near parallel", 27, 20000, obbsat::test::near_parallel_pair);
    EXPECT_GT(classes['S'], 1000);
    EXPECT_GT(classes['O'], 1000);
}

TEST(pose_cross_check64, rotation_lengths_from_1e_60_to_1e60) {
    auto classes = cross_check("scaled rotations", 28, 20000, obbsat::test::scaled_rotation_pair);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes[c], 1000) << c;
    }
}

TEST(pose_cross_check64, invalid_poses_are_refused) {
    const rect_pose64 good{{500000.125, 6e6}, {10, 5}, {1, 0}};
    rect_pose64 bad = good;
    bad.half_extents.y = -1;
    EXPECT_THROW(obbsat::oracle::classify(good, bad), std::invalid_argument);
    bad = good;
    bad.rotation = {0, 0};
    EXPECT_THROW(obbsat::oracle::classify(bad, good), std::invalid_argument);
    bad = good;
    bad.center.x = INFINITY;
    EXPECT_THROW(obbsat::oracle::classify(good, bad), std::invalid_argument);
    EXPECT_STREQ(obbsat::oracle::pose_defect(bad), "a value is not finite");
    EXPECT_EQ(obbsat::oracle::pose_defect(good), nullptr);
}

}  // namespace
