// The double contact and distance references (obbsat/ref/contact.hpp and
// distance.hpp over rect_pose64 and rect64) against the float ones on input
// that float represents exactly, and on hand-worked cases at UTM-like
// coordinates that float cannot hold.
//
// What holds, and is checked:
//   - On axis-aligned poses (rotation (±1, 0) or (0, ±1)) with coordinates
//     on a grid of eighths, every step except the clipping quotient is exact
//     in both precisions, so the double contact equals the widened float one
//     in normal, depth, point count, feature keys and separations, and in the
//     positions up to the rounding of that quotient (float ulps of the
//     pair's scale, along the face), except that the rounding of a clipped
//     point can leave two points a few ulps apart in one precision where the
//     other keeps one (the repeat rule of step 7). Their corners, where both precisions
//     choose the same face (a near tie of two faces may go either way, as a
//     corner face's normal is scaled by a rounded 1/length), give the same
//     point counts (with the same exception) and features, the other values within two float ulps of the scale (a
//     corner face's normal is scaled by a rounded 1/length). the distance is the
//     same once rounded to float (its square is exact in both, and a double
//     square root rounded to float is the float one), the closest points
//     within one float ulp of the scale (the quotient 1/ee rounds).
//   - On general float pairs (any rotation), the two precisions may choose a
//     different reference face or feature where two candidates tie within
//     float rounding, so no exact agreement is stated there; where they
//     choose the same face, normal and depth agree within 2^-16 of the pair's
//     scale (the float steps are accurate to a few float ulps of it).
#include "test_support/contact_cases.hpp"
#include "test_support/pose_cases64.hpp"

#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>
#include <obbsat/ref/pose_corners.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>

namespace {

using obbsat::contact;
using obbsat::contact64;
using obbsat::rect;
using obbsat::rect64;
using obbsat::rect_pose;
using obbsat::rect_pose64;

rect_pose64 widened(const rect_pose& p) {
    return {{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}};
}

rect64 widened(const rect& r) {
    return {{r.ul.x, r.ul.y}, {r.ur.x, r.ur.y}, {r.lr.x, r.lr.y}, {r.ll.x, r.ll.y}};
}

bool same_feature(const obbsat::contact_feature& f, const obbsat::contact_feature& g) {
    return std::memcmp(&f, &g, sizeof f) == 0;
}

/// Axis-aligned pairs on a grid of eighths: centers within 8 of each other,
/// half extents 1/8 to 4, every rotation a quarter turn.
obbsat::test::pose_pairs grid_pairs(std::uint64_t seed, std::size_t count) {
    obbsat::seeded_random random(seed);
    const float turns[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    auto eighths = [&](int lo, int hi) { return static_cast<float>(lo + static_cast<int>(random.below(
                                                                       static_cast<std::uint32_t>(hi - lo + 1)))) /
                                                8.0f; };
    obbsat::test::pose_pairs out;
    for (std::size_t i = 0; i < count; ++i) {
        const auto& ta = turns[random.below(4)];
        const auto& tb = turns[random.below(4)];
        out.a.push_back(rect_pose{{eighths(-64, 64), eighths(-64, 64)}, {eighths(1, 32), eighths(1, 32)},
                                  {ta[0], ta[1]}});
        const rect_pose& a = out.a.back();
        out.b.push_back(rect_pose{{a.center.x + eighths(-64, 64), a.center.y + eighths(-64, 64)},
                                  {eighths(1, 32), eighths(1, 32)},
                                  {tb[0], tb[1]}});
    }
    return out;
}

/// The scale of a pair: its distance from the origin o plus its sizes.
double scale_of(const rect_pose& a, const rect_pose& b) {
    return std::fabs(a.center.x) + std::fabs(a.center.y) + std::fabs(b.center.x - a.center.x) +
           std::fabs(b.center.y - a.center.y) + a.half_extents.x + a.half_extents.y + b.half_extents.x +
           b.half_extents.y;
}

/// How many grid pairs one precision gives one point where the other gives two.
std::size_t merged_points = 0;

/// The double contact d against the float one f of a grid pair: the same
/// point count (but see below) and features; normal, depth and separations equal when `exact`
/// (poses), else within two float ulps of the scale (corners, whose face
/// normals are scaled by a rounded 1/length); positions within that too.
void expect_grid_agreement(const contact64& d, const contact& f, double scale, bool exact, const std::string& what) {
    const double ulps = exact ? 0.0 : std::ldexp(scale, -22);
    EXPECT_LE(std::fabs(d.nx - double{f.nx}), exact ? 0.0 : 0x1p-22) << what;
    EXPECT_LE(std::fabs(d.ny - double{f.ny}), exact ? 0.0 : 0x1p-22) << what;
    EXPECT_LE(std::fabs(d.depth - double{f.depth}), ulps) << what;
    if (d.point_count != f.point_count) {
        // The one exception: the rounding of a clipped point leaves it a few
        // ulps from the other end in one precision (two points) and on it in
        // the other (kept once).
        ASSERT_EQ(f.point_count + d.point_count, 3u) << what;
        const double near = std::ldexp(scale, -22);
        const bool float_two = f.point_count == 2;
        const double x0 = float_two ? f.points[0].x : d.points[0].x, x1 = float_two ? f.points[1].x : d.points[1].x;
        const double y0 = float_two ? f.points[0].y : d.points[0].y, y1 = float_two ? f.points[1].y : d.points[1].y;
        EXPECT_LE(std::fabs(x0 - x1), near) << what;
        EXPECT_LE(std::fabs(y0 - y1), near) << what;
        ++merged_points;
        return;
    }
    for (std::uint32_t p = 0; p < f.point_count; ++p) {
        EXPECT_TRUE(same_feature(d.points[p].feature, f.points[p].feature)) << what;
        EXPECT_LE(std::fabs(d.points[p].separation - double{f.points[p].separation}), ulps) << what;
        EXPECT_LE(std::fabs(d.points[p].x - double{f.points[p].x}), std::ldexp(scale, -22)) << what;
        EXPECT_LE(std::fabs(d.points[p].y - double{f.points[p].y}), std::ldexp(scale, -22)) << what;
    }
}

TEST(contact_ref64, equals_the_float_reference_on_axis_aligned_grid_pairs) {
    const obbsat::test::pose_pairs pairs = grid_pairs(64, 40000);
    std::size_t with_points = 0, other_corner_face = 0;
    for (std::size_t i = 0; i < pairs.a.size(); ++i) {
        const rect_pose& a = pairs.a[i];
        const rect_pose& b = pairs.b[i];
        const double scale = scale_of(a, b);
        for (const float margin : {0.0f, 0.5f}) {
            const contact f = obbsat::ref::contact_of(a, b, margin);
            const contact64 d = obbsat::ref::contact_of(widened(a), widened(b), double{margin});
            expect_grid_agreement(d, f, scale, true, "pose pair " + std::to_string(i));
            const rect ca = obbsat::ref::corners_of(a), cb = obbsat::ref::corners_of(b);
            const contact fc = obbsat::ref::contact_of(ca, cb, margin);
            const contact64 dc = obbsat::ref::contact_of(widened(ca), widened(cb), double{margin});
            // Corners scale each face by a rounded 1/length, so a near tie of
            // two faces may go either way: compared only where both choose the
            // same normal.
            if (std::fabs(dc.nx - double{fc.nx}) + std::fabs(dc.ny - double{fc.ny}) > 0x1p-20) {
                ++other_corner_face;
                continue;
            }
            expect_grid_agreement(dc, fc, scale, false, "corner pair " + std::to_string(i));
            with_points += f.point_count > 0;
        }
        const obbsat::closest_points fd = obbsat::ref::distance_of(a, b);
        const obbsat::closest_points64 dd = obbsat::ref::distance_of(widened(a), widened(b));
        // The squared distance is exact in both, and a double square root
        // rounded to float is the float square root (53 >= 2 * 24 + 2 bits).
        EXPECT_EQ(static_cast<float>(dd.distance), fd.distance) << i;
        const double ulp = std::ldexp(scale_of(a, b), -23);
        for (const auto& [wide, narrow] : {std::pair<double, float>{dd.ax, fd.ax}, {dd.ay, fd.ay}, {dd.bx, fd.bx},
                                           {dd.by, fd.by}}) {
            EXPECT_LE(std::fabs(wide - double{narrow}), ulp) << i;
        }
        if (::testing::Test::HasFailure()) {
            return;
        }
    }
    EXPECT_GT(with_points, pairs.a.size() / 4);
    EXPECT_LT(merged_points, with_points / 100);
    EXPECT_LT(other_corner_face, pairs.a.size() / 100);
}

TEST(contact_ref64, agrees_with_the_float_reference_where_both_choose_the_same_face) {
    const obbsat::test::pose_pairs pairs = obbsat::test::random_pairs(65, 100000);
    std::size_t same_choice = 0;
    for (std::size_t i = 0; i < pairs.a.size(); ++i) {
        const rect_pose& a = pairs.a[i];
        const rect_pose& b = pairs.b[i];
        const contact f = obbsat::ref::contact_of(a, b);
        const contact64 d = obbsat::ref::contact_of(widened(a), widened(b));
        const bool same = f.point_count == d.point_count &&
                          (f.point_count == 0 || same_feature(f.points[0].feature, d.points[0].feature)) &&
                          ((f.nx > 0) == (d.nx > 0)) && ((f.ny > 0) == (d.ny > 0));
        if (!same) {
            continue;
        }
        ++same_choice;
        const double tolerance = std::ldexp(scale_of(a, b), -16);
        EXPECT_LE(std::fabs(d.nx - double{f.nx}), std::ldexp(1.0, -16)) << i;
        EXPECT_LE(std::fabs(d.ny - double{f.ny}), std::ldexp(1.0, -16)) << i;
        EXPECT_LE(std::fabs(d.depth - double{f.depth}), tolerance) << i;
        for (std::uint32_t p = 0; p < f.point_count; ++p) {
            EXPECT_LE(std::fabs(d.points[p].x - double{f.points[p].x}), tolerance) << i;
            EXPECT_LE(std::fabs(d.points[p].separation - double{f.points[p].separation}), tolerance) << i;
        }
        if (::testing::Test::HasFailure()) {
            return;
        }
    }
    EXPECT_GT(same_choice, pairs.a.size() * 99 / 100);
}

TEST(contact_ref64, computes_in_double_at_utm_coordinates) {
    // Two unit squares at an easting float cannot hold (float's step there is
    // 1/32): B overlaps A by 1/1024, which only double sees.
    const rect_pose64 a{{500000.0009765625, 5000000.0}, {1, 1}, {1, 0}};
    const rect_pose64 b{{500002.0, 5000000.0}, {1, 1}, {1, 0}};
    const contact64 c = obbsat::ref::contact_of(a, b);
    EXPECT_EQ(c.nx, 1.0);
    EXPECT_EQ(c.ny, 0.0);
    EXPECT_EQ(c.depth, 0x1p-10);
    ASSERT_EQ(c.point_count, 2u);
    EXPECT_EQ(c.points[0].x, 500001.0);
    EXPECT_EQ(c.points[0].separation, -0x1p-10);
    const rect_pose64 apart{{500002.0 + 0x1p-9, 5000000.0}, {1, 1}, {1, 0}};
    const obbsat::closest_points64 d = obbsat::ref::distance_of(a, apart);
    EXPECT_EQ(d.distance, 0x1p-9 - 0x1p-10);
    EXPECT_EQ(obbsat::ref::distance_of(a, b).distance, 0.0);
    // The same on corners.
    const contact64 q = obbsat::ref::contact_of(obbsat::test::corners64(a), obbsat::test::corners64(b));
    EXPECT_EQ(q.depth, 0x1p-10);
    EXPECT_EQ(q.point_count, 2u);
}

TEST(contact_ref64, accepts_in_double) {
    EXPECT_TRUE(obbsat::ref::pose_accepted(rect_pose64{{0, 0}, {1, 1}, {1e-100, 0}})) << "a normal double square";
    EXPECT_FALSE(obbsat::ref::pose_accepted(rect_pose64{{0, 0}, {1, 1}, {1e-200, 0}}));
    EXPECT_FALSE(obbsat::ref::pose_accepted(rect_pose64{{0, 0}, {1, 1}, {1e200, 0}}));
    EXPECT_TRUE(obbsat::ref::corners_accepted(rect64{{0, 1e-30}, {1e-30, 1e-30}, {1e-30, 0}, {0, 0}}))
        << "a quad too small for float's normal range";
    EXPECT_FALSE(obbsat::ref::corners_accepted(rect64{{0, 0}, {1, 1}, {1, 0}, {0, 1}})) << "self-intersecting";
}

}  // namespace
