// The contact reference (obbsat/ref/contact.hpp) on hand-worked cases whose
// every value is exact in float32: the normal, depth, points, separations and
// feature keys as the steps give them, worked out by hand in the comments.
#include <obbsat/ref/contact.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace {

using obbsat::contact;
using obbsat::contact_feature;
using obbsat::feature_type;
using obbsat::point;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::ref::contact_of;

constexpr feature_type vertex = feature_type::vertex;
constexpr feature_type face = feature_type::face;

rect_pose box(float cx, float cy, float hx, float hy, float c = 1.0f, float s = 0.0f) {
    return rect_pose{{cx, cy}, {hx, hy}, {c, s}};
}

/// The corners of an axis-aligned box, UL, UR, LR, LL (clockwise).
rect corners(float cx, float cy, float hx, float hy) {
    return rect{{cx - hx, cy + hy}, {cx + hx, cy + hy}, {cx + hx, cy - hy}, {cx - hx, cy - hy}};
}

void expect_point(const contact& c, int k, float x, float y, float separation, contact_feature f) {
    SCOPED_TRACE("point " + std::to_string(k));
    EXPECT_EQ(c.points[k].x, x);
    EXPECT_EQ(c.points[k].y, y);
    EXPECT_EQ(c.points[k].separation, separation);
    EXPECT_EQ(c.points[k].feature.index_a, f.index_a);
    EXPECT_EQ(c.points[k].feature.type_a, f.type_a);
    EXPECT_EQ(c.points[k].feature.index_b, f.index_b);
    EXPECT_EQ(c.points[k].feature.type_b, f.type_b);
}

void expect_unused_point_zero(const contact& c, int k) {
    const unsigned char zeros[sizeof c.points[0]] = {};
    EXPECT_EQ(std::memcmp(&c.points[k], zeros, sizeof zeros), 0) << "point " << k << " is unused";
}

// B's bottom face (y = 0.75) sinks 0.25 into A's top face (y = 1), offset by
// 0.5 in x: both separate by -0.25, A's face 0 is kept (A preferred on a tie);
// B's face 2 (LR (1.5, .75) to LL (-.5, .75)) is clipped at A's UR side, τ from
// 5 to 1 against T = 4: λT = 1/4, the point (1, .75).
TEST(contact_ref, face_against_face_gives_two_points) {
    const contact c = contact_of(box(0, 0, 1, 1), box(0.5f, 1.75f, 1, 1));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, 1.0f, 0.75f, -0.25f, {1, vertex, 2, face});
    expect_point(c, 1, -0.5f, 0.75f, -0.25f, {0, face, 3, vertex});
}

// The same far from the origin: every value shifted by 1e6 exactly (the
// boxes are taken relative to A's center, so nothing is lost).
TEST(contact_ref, far_from_the_origin_is_the_same_shifted) {
    const float far = 1.0e6f;
    const contact c = contact_of(box(far, far, 1, 1), box(far + 0.5f, far + 1.75f, 1, 1));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, far + 1.0f, far + 0.75f, -0.25f, {1, vertex, 2, face});
    expect_point(c, 1, far - 0.5f, far + 0.75f, -0.25f, {0, face, 3, vertex});
}

// B turned 45° (rotation (1, 1), so scaled by √2): corners UL (-1, 1.75),
// UR (0, 2.75), LR (1, 1.75), LL (0, .75). Its corner LL sinks 0.25 into A's
// top face; B's faces separate by -1.25/√2 at best. The incident faces 2 and 3
// tie (-1/√2 each): face 2, LR to LL. LR is 0.75 above A, beyond the margin.
TEST(contact_ref, corner_into_face_gives_one_point) {
    const rect_pose b = box(0, 1.75f, 0.5f, 0.5f, 1, 1);
    const contact c = contact_of(box(0, 0, 1, 1), b);
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    ASSERT_EQ(c.point_count, 1u);
    expect_point(c, 0, 0.0f, 0.75f, -0.25f, {0, face, 3, vertex});
    expect_unused_point_zero(c, 1);

    // With a margin of 1, LR (0.75 above A's face) is kept too, first.
    const contact speculative = contact_of(box(0, 0, 1, 1), b, 1.0f);
    ASSERT_EQ(speculative.point_count, 2u);
    expect_point(speculative, 0, 1.0f, 1.75f, 0.75f, {0, face, 2, vertex});
    expect_point(speculative, 1, 0.0f, 0.75f, -0.25f, {0, face, 3, vertex});
}

// A turned 45° pokes its corner UR (0, 1) 0.25 into B's bottom face: B's face
// separates by -0.25, A's by -1.25/√2 at most, so B's face is the reference
// (flip) and the normal, from A to B, is minus B's face normal (0, -1).
TEST(contact_ref, the_reference_face_is_b_when_b_separates_clearly_more) {
    const contact c = contact_of(box(0, 0, 0.5f, 0.5f, 1, 1), box(0, 1.75f, 1, 1));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_TRUE(std::signbit(c.nx)) << "minus u: the sign of B's normal's zero is flipped";
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    ASSERT_EQ(c.point_count, 1u);
    expect_point(c, 0, 0.0f, 1.0f, -0.25f, {1, vertex, 2, face});
}

// B (1 by 1) wholly inside A (8 by 4): A's top face and B's bottom face
// separate by -2 each; A's is kept, B's bottom edge lies 2 below A's top.
TEST(contact_ref, one_box_deep_inside_the_other) {
    const contact c = contact_of(box(0, 0, 4, 2), box(1, 0.5f, 0.5f, 0.5f));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 2.0f);
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, 1.5f, 0.0f, -2.0f, {0, face, 2, vertex});
    expect_point(c, 1, 0.5f, 0.0f, -2.0f, {0, face, 3, vertex});
}

// B's bottom face lies on A's top face: depth +0, separations 0, points kept
// at margin 0. Moved 0.5 apart, no points unless the margin reaches 0.5.
TEST(contact_ref, exact_touching_has_depth_zero_and_points) {
    const contact c = contact_of(box(0, 0, 1, 1), box(0.5f, 2, 1, 1));
    EXPECT_EQ(c.depth, 0.0f);
    EXPECT_FALSE(std::signbit(c.depth)) << "0 - 0 is +0";
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, 1.0f, 1.0f, 0.0f, {1, vertex, 2, face});
    expect_point(c, 1, -0.5f, 1.0f, 0.0f, {0, face, 3, vertex});

    const contact apart = contact_of(box(0, 0, 1, 1), box(0.5f, 2.5f, 1, 1));
    EXPECT_EQ(apart.depth, -0.5f);
    EXPECT_EQ(apart.ny, 1.0f);
    EXPECT_EQ(apart.point_count, 0u);
    expect_unused_point_zero(apart, 0);
    expect_unused_point_zero(apart, 1);

    const contact speculative = contact_of(box(0, 0, 1, 1), box(0.5f, 2.5f, 1, 1), 0.5f);
    ASSERT_EQ(speculative.point_count, 2u);
    expect_point(speculative, 0, 1.0f, 1.5f, 0.5f, {1, vertex, 2, face});
    expect_point(speculative, 1, -0.5f, 1.5f, 0.5f, {0, face, 3, vertex});
    const contact short_margin = contact_of(box(0, 0, 1, 1), box(0.5f, 2.5f, 1, 1), 0.25f);
    EXPECT_EQ(short_margin.point_count, 0u);
}

// A tilted pair that touches exactly (rotations (8, -15) and (15, 8) are at
// right angles, and the faces meet): the depth rounds to 0, but the points'
// separations dot(p - q1, u) round a few ulps above it. The nearer point is
// kept at margin 0 all the same, at the place a margin of a few ulps keeps it,
// its separation read as the margin.
TEST(contact_ref, a_tilted_touching_pair_keeps_its_nearer_point_at_margin_zero) {
    const rect_pose a = box(1, -1, 0.5f, 3, 8, -15), b = box(-66, -56, 2, 0.5f, 15, 8);
    const contact c = contact_of(a, b);
    EXPECT_EQ(c.depth, 0.0f);
    ASSERT_GE(c.point_count, 1u);
    const contact wider = contact_of(a, b, 0x1p-10f);
    ASSERT_GE(wider.point_count, c.point_count);
    float nearest = wider.points[0].separation;
    for (unsigned k = 1; k < wider.point_count; ++k) {
        nearest = std::fmin(nearest, wider.points[k].separation);
    }
    EXPECT_GT(nearest, 0.0f) << "the case needs a separation that rounds above 0";
    for (unsigned k = 0; k < c.point_count; ++k) {
        SCOPED_TRACE("point " + std::to_string(k));
        EXPECT_EQ(c.points[k].separation, 0.0f);
        bool found = false;
        for (unsigned w = 0; w < wider.point_count; ++w) {
            found = found || (c.points[k].x == wider.points[w].x && c.points[k].y == wider.points[w].y);
        }
        EXPECT_TRUE(found) << "a point the wider margin keeps too";
    }

    // Swapped, the same touch from B's side.
    EXPECT_GE(contact_of(b, a).point_count, 1u);
}

// A segment (hy = 0) four long lying on A's top face: clipped at both of A's
// sides. A point (both half extents 0) 0.25 inside A: one point, not twice.
TEST(contact_ref, zero_half_extents) {
    const contact segment = contact_of(box(0, 0, 1, 1), box(0, 1, 2, 0));
    EXPECT_EQ(segment.ny, 1.0f);
    EXPECT_EQ(segment.depth, 0.0f);
    ASSERT_EQ(segment.point_count, 2u);
    expect_point(segment, 0, 1.0f, 1.0f, 0.0f, {1, vertex, 2, face});
    expect_point(segment, 1, -1.0f, 1.0f, 0.0f, {0, vertex, 2, face});

    const contact dot = contact_of(box(0, 0, 1, 1), box(0.5f, 0.75f, 0, 0));
    EXPECT_EQ(dot.ny, 1.0f);
    EXPECT_EQ(dot.depth, 0.25f);
    ASSERT_EQ(dot.point_count, 1u);
    expect_point(dot, 0, 0.5f, 0.75f, -0.25f, {0, face, 2, vertex});
    expect_unused_point_zero(dot, 1);
}

// A turned 90° (rotation (0, 1)), 4 long in y: its face 1 (UR (-1, 2) to
// LR (1, 2)) faces up, normal (c, s) = (0, 1); B's bottom sinks 0.5 into it.
TEST(contact_ref, rotated_reference_face) {
    const contact c = contact_of(box(0, 0, 2, 1, 0, 1), box(0, 2.5f, 1, 1));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.5f);
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, 1.0f, 1.5f, -0.5f, {1, face, 2, vertex});
    expect_point(c, 1, -1.0f, 1.5f, -0.5f, {1, face, 3, vertex});
}

// A box moved a whole side along its own normal gives the normal negated
// when the pair is swapped: from A to B is from B to A reversed.
TEST(contact_ref, swapping_the_pair_reverses_the_normal) {
    const contact c = contact_of(box(0.5f, 1.75f, 1, 1), box(0, 0, 1, 1));
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, -1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    EXPECT_EQ(c.point_count, 2u);
}

// Corners: the face-against-face case as quads, in both windings, gives the
// pose answer; the face normals come from the edges, here 2 long.
TEST(contact_ref, corners_in_either_winding) {
    const rect a = corners(0, 0, 1, 1), b = corners(0.5f, 1.75f, 1, 1);
    ASSERT_TRUE(obbsat::ref::corners_accepted(a));
    const contact c = contact_of(a, b);
    EXPECT_EQ(c.nx, 0.0f);
    EXPECT_EQ(c.ny, 1.0f);
    EXPECT_EQ(c.depth, 0.25f);
    ASSERT_EQ(c.point_count, 2u);
    expect_point(c, 0, 1.0f, 0.75f, -0.25f, {1, vertex, 2, face});
    expect_point(c, 1, -0.5f, 0.75f, -0.25f, {0, face, 3, vertex});

    // Mirrored in x: UL and UR swap sides, so the quads turn counter-clockwise.
    const rect ma{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    const rect mb{{0.5f, 2.75f}, {-1.5f, 2.75f}, {-1.5f, 0.75f}, {0.5f, 0.75f}};
    ASSERT_TRUE(obbsat::ref::corners_accepted(ma));
    const contact m = contact_of(ma, mb);
    EXPECT_EQ(m.ny, 1.0f);
    EXPECT_EQ(m.depth, 0.25f);
    ASSERT_EQ(m.point_count, 2u);
    expect_point(m, 0, -1.0f, 0.75f, -0.25f, {1, vertex, 2, face});
    expect_point(m, 1, 0.5f, 0.75f, -0.25f, {0, face, 3, vertex});
}

TEST(contact_ref, corners_that_are_not_a_strictly_convex_quad_are_refused) {
    EXPECT_FALSE(obbsat::ref::corners_accepted(rect{{0, 0}, {1, 1}, {1, 0}, {0, 1}})) << "self-intersecting";
    EXPECT_FALSE(obbsat::ref::corners_accepted(rect{{0, 1}, {1, 1}, {1, 1}, {0, 0}})) << "two equal corners";
    EXPECT_FALSE(obbsat::ref::corners_accepted(rect{{0, 1}, {1, 1}, {2, 1}, {0, 0}})) << "three on a line";
    EXPECT_FALSE(obbsat::ref::corners_accepted(rect{{0, 2}, {2, 2}, {0.5f, 0.5f}, {0, 0}})) << "reflex corner";
    EXPECT_TRUE(obbsat::ref::corners_accepted(rect{{0, 2}, {2, 2}, {1.5f, 0.5f}, {0, 0}}))
        << "convex, not a rectangle";
    EXPECT_FALSE(obbsat::ref::pose_accepted(box(0, 0, 1, 1, 1e-30f, 0))) << "rotation too short";
    EXPECT_TRUE(obbsat::ref::pose_accepted(box(0, 0, 1, 1, 1e-10f, 0)));
}

}  // namespace
