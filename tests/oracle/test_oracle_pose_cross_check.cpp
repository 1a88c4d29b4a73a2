// The pose oracle against an independent construction in GMP rationals: the
// four true corners of each pose, C ± hx·(c, s) ± hy·(−s, c), computed
// exactly, and the two quads they bound compared by rational_model.hpp
// (segment intersection, ray-crossing containment, the area of the clipped
// intersection): no axis and no slack anywhere. The pairs come from every
// make of pose_cases.hpp. Any difference fails with the pair in hex floats.
#include "pose_cases.hpp"
#include "rational_model.hpp"

#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace {

using obbsat::rect_pose;
using obbsat::test::rational_point;

std::string show(const rect_pose& p) {
    char text[200];
    std::snprintf(text, sizeof text, "{c %a,%a h %a,%a r %a,%a}", static_cast<double>(p.center.x),
                  static_cast<double>(p.center.y), static_cast<double>(p.half_extents.x),
                  static_cast<double>(p.half_extents.y), static_cast<double>(p.rotation.x),
                  static_cast<double>(p.rotation.y));
    return text;
}

mpq_class exact(float v) { return mpq_class(static_cast<double>(v)); }

// UL, UR, LR, LL of the pose's set, exactly.
obbsat::test::rational_corners true_corners(const rect_pose& p) {
    const mpq_class cx = exact(p.center.x), cy = exact(p.center.y);
    const mpq_class hx = exact(p.half_extents.x), hy = exact(p.half_extents.y);
    const mpq_class c = exact(p.rotation.x), s = exact(p.rotation.y);
    const mpq_class ux = hx * c, uy = hx * s;    // hx·(c, s)
    const mpq_class vx = -hy * s, vy = hy * c;   // hy·(−s, c)
    return {rational_point{cx - ux + vx, cy - uy + vy}, rational_point{cx + ux + vx, cy + uy + vy},
            rational_point{cx + ux - vx, cy + uy - vy}, rational_point{cx - ux - vx, cy - uy - vy}};
}

char model_contact(const rect_pose& a, const rect_pose& b) {
    return obbsat::test::rational_contact(obbsat::test::rational_region_of(true_corners(a)),
                                          obbsat::test::rational_region_of(true_corners(b)));
}

// The four-axis test in plain double, as a first attempt would write it: to
// count the pairs where rounding alone gets the class wrong.
char naive_double_contact(const rect_pose& a, const rect_pose& b) {
    const double ca = a.rotation.x, sa = a.rotation.y, cb = b.rotation.x, sb = b.rotation.y;
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const double hxb = b.half_extents.x, hyb = b.half_extents.y;
    const double dx = static_cast<double>(b.center.x) - a.center.x;
    const double dy = static_cast<double>(b.center.y) - a.center.y;
    const double na = ca * ca + sa * sa, nb = cb * cb + sb * sb;
    const double p = std::fabs(ca * cb + sa * sb), q = std::fabs(ca * sb - sa * cb);
    const double slacks[4] = {
        hxa * na + hxb * p + hyb * q - std::fabs(dx * ca + dy * sa),
        hya * na + hxb * q + hyb * p - std::fabs(-dx * sa + dy * ca),
        hxb * nb + hxa * p + hya * q - std::fabs(dx * cb + dy * sb),
        hyb * nb + hxa * q + hya * p - std::fabs(-dx * sb + dy * cb),
    };
    bool all_positive = hxa > 0 && hya > 0 && hxb > 0 && hyb > 0;
    for (const double slack : slacks) {
        if (slack < 0) {
            return 'S';
        }
        all_positive = all_positive && slack > 0;
    }
    return all_positive ? 'O' : 'T';
}

// Returns the model's letter; fails the test on a difference.
char expect_agreement(const rect_pose& a, const rect_pose& b) {
    const char model = model_contact(a, b);
    const char oracle = obbsat::oracle::contact_letter(obbsat::oracle::classify(a, b));
    EXPECT_EQ(oracle, model) << "A " << show(a) << "\nB " << show(b);
    if (model == 'T') {
        // Touching pairs always take the exact path; check the unfiltered one too.
        EXPECT_EQ(obbsat::oracle::contact_letter(obbsat::oracle::classify_exact(a, b)), model)
            << "A " << show(a) << "\nB " << show(b);
    }
    return model;
}

// Runs `count` pairs from `make(random)` and prints the classes found and how
// many pairs plain double arithmetic classifies wrongly (key 'D' of the result).
std::map<char, int> cross_check(const char* name, std::uint64_t seed, int count,
                                obbsat::test::pose_pair (*make)(obbsat::seeded_random&)) {
    obbsat::seeded_random random(seed);
    std::map<char, int> classes;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count && !::testing::Test::HasFailure(); ++i) {
        const auto [a, b] = make(random);
        const char model = expect_agreement(a, b);
        ++classes[model];
        classes['D'] += naive_double_contact(a, b) != model ? 1 : 0;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ model    ] %-24s %6d pairs  S %6d  T %6d  O %6d  double wrong %5d  %.1f s\n", name, count,
                classes['S'], classes['T'], classes['O'], classes['D'], seconds);
    return classes;
}

TEST(pose_cross_check, lattice_pairs) {
    const auto classes = cross_check("lattice", 1, 30000, obbsat::test::lattice_pair);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 3000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_far_from_the_origin) {
    const auto classes = cross_check("lattice at (1e7, 3e7)", 2, 30000, obbsat::test::lattice_pair_far);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_with_rotation_vectors_far_from_unit) {
    const auto classes =
        cross_check("lattice, 2^k rotations", 3, 30000, obbsat::test::lattice_pair_scaled_rotations);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
}

TEST(pose_cross_check, lattice_pairs_with_rotation_components_of_two_scales) {
    // Slacks decided far below double precision: plain double gets some wrong.
    const auto classes =
        cross_check("lattice, two-scale turns", 7, 40000, obbsat::test::lattice_pair_two_scale_rotations);
    for (const char c : {'S', 'T', 'O'}) {
        EXPECT_GT(classes.at(c), 2000) << c;
    }
    EXPECT_GT(classes.at('D'), 150);
}

TEST(pose_cross_check, a_corner_on_the_other_outline) {
    const auto classes = cross_check("corner on outline", 4, 40000, obbsat::test::corner_on_outline);
    for (const char c : {'S', 'O'}) {
        EXPECT_GT(classes.at(c), 10000) << c;
    }
}

TEST(pose_cross_check, a_corner_on_the_other_outline_far_from_the_origin) {
    const auto classes = cross_check("corner on outline, far", 5, 30000, obbsat::test::corner_on_outline_far);
    for (const char c : {'S', 'O'}) {
        EXPECT_GT(classes.at(c), 5000) << c;
    }
}

TEST(pose_cross_check, a_point_nearly_on_a_segment_line) {
    // Sides of the line decided below the rounding of the centers' difference.
    const auto classes = cross_check("point along a segment", 8, 20000, obbsat::test::point_along_a_segment);
    EXPECT_GT(classes.at('S'), 10000);
    EXPECT_GT(classes.at('T'), 1000);
    EXPECT_GT(classes.at('D'), 1000);
}

TEST(pose_cross_check, random_pairs) {
    const auto classes = cross_check("random", 6, 20000, obbsat::test::random_pair);
    EXPECT_GT(classes.at('S'), 10000);
    EXPECT_GT(classes.at('O'), 1500);
}

}  // namespace
