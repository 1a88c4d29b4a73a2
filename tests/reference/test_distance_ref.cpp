// The distance reference (obbsat/ref/distance.hpp) on hand-worked cases whose
// every value is exact in float32 (but the one square root), worked out by
// hand in the comments, in the candidate order of step D2.
#include <obbsat/ref/distance.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using obbsat::closest_points;
using obbsat::rect;
using obbsat::rect_pose;
using obbsat::ref::distance_of;

rect_pose box(float cx, float cy, float hx, float hy) { return rect_pose{{cx, cy}, {hx, hy}, {1, 0}}; }

rect corners(float cx, float cy, float hx, float hy) {
    return rect{{cx - hx, cy + hy}, {cx + hx, cy + hy}, {cx + hx, cy - hy}, {cx - hx, cy - hy}};
}

void expect_closest(const closest_points& c, float distance, float ax, float ay, float bx, float by) {
    EXPECT_EQ(c.distance, distance);
    EXPECT_EQ(c.ax, ax);
    EXPECT_EQ(c.ay, ay);
    EXPECT_EQ(c.bx, bx);
    EXPECT_EQ(c.by, by);
}

// B's left face (x = 2) one from A's right face (x = 1), B higher by 0.5:
// A's edge 1 (UR to LR) and B's LL (2, -0.5) give d2 = 1 first.
TEST(distance_ref, face_to_face) {
    expect_closest(distance_of(box(0, 0, 1, 1), box(3, 0.5f, 1, 1)), 1.0f, 1.0f, -0.5f, 2.0f, -0.5f);
    expect_closest(distance_of(corners(0, 0, 1, 1), corners(3, 0.5f, 1, 1)), 1.0f, 1.0f, -0.5f, 2.0f, -0.5f);
}

// A's UR (1, 1) and B's LL (3, 3): d2 = 8, first on A's edge 0 (clamped to its end).
TEST(distance_ref, corner_to_corner) {
    expect_closest(distance_of(box(0, 0, 1, 1), box(4, 4, 1, 1)), std::sqrt(8.0f), 1.0f, 1.0f, 3.0f, 3.0f);
}

// A point two from A's right face: the foot on A's edge 1.
TEST(distance_ref, a_point) {
    expect_closest(distance_of(box(0, 0, 1, 1), box(3, 0, 0, 0)), 2.0f, 1.0f, 0.0f, 3.0f, 0.0f);
}

// Far from the origin: the same, shifted exactly (the boxes are taken relative to A's center).
TEST(distance_ref, far_from_the_origin) {
    const float far = 1.0e6f;
    expect_closest(distance_of(box(far, far, 1, 1), box(far + 3, far + 0.5f, 1, 1)), 1.0f, far + 1.0f, far - 0.5f,
                   far + 2.0f, far - 0.5f);
}

// Overlapping, touching and one inside the other collide: every field +0.
TEST(distance_ref, colliding_pairs_are_all_zero) {
    for (const rect_pose& b : {box(1, 0.5f, 1, 1), box(2, 0.5f, 1, 1), box(0.25f, 0, 0.1f, 0.1f)}) {
        const closest_points c = distance_of(box(0, 0, 1, 1), b);
        expect_closest(c, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
        EXPECT_FALSE(std::signbit(c.distance) || std::signbit(c.ax) || std::signbit(c.by));
    }
    expect_closest(distance_of(corners(0, 0, 1, 1), corners(2, 0.5f, 1, 1)), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f);
}

}  // namespace
