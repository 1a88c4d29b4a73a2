// The bounds of obbsat/ref/bounds.hpp against exact arithmetic: every corner
// of the exact point set lies inside them, and they are no looser than the
// contract's margin allows (so bounds of ±inf would fail).
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/scene.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using obbsat::rect_pose;
using obbsat::ref::box_bounds;

mpq_class exact(float v) { return mpq_class(static_cast<double>(v)); }

/// The exact extreme x and y of the pose's four corners.
struct exact_extent {
    mpq_class lo_x, lo_y, hi_x, hi_y;
};

exact_extent exact_extent_of(const rect_pose& p) {
    exact_extent out;
    bool first = true;
    for (const int a : {-1, 1}) {
        for (const int b : {-1, 1}) {
            const mpq_class u = exact(p.half_extents.x) * a;
            const mpq_class v = exact(p.half_extents.y) * b;
            const mpq_class x = exact(p.center.x) + u * exact(p.rotation.x) - v * exact(p.rotation.y);
            const mpq_class y = exact(p.center.y) + u * exact(p.rotation.y) + v * exact(p.rotation.x);
            if (first || x < out.lo_x) out.lo_x = x;
            if (first || x > out.hi_x) out.hi_x = x;
            if (first || y < out.lo_y) out.lo_y = y;
            if (first || y > out.hi_y) out.hi_y = y;
            first = false;
        }
    }
    return out;
}

/// Poses across every scale the contract covers: near and far from the
/// origin, tiny and huge, unit and very long or short rotation vectors, zero
/// extents, subnormal values.
std::vector<rect_pose> hard_poses() {
    obbsat::seeded_random random(20261123);
    std::vector<rect_pose> poses;
    const float scales[] = {1e-38f, 1e-20f, 1e-6f, 1.0f, 1e3f, 1e7f, 3e7f, 1e15f, 1e30f};
    const float rotation_lengths[] = {1e-20f, 1e-3f, 1.0f, 7.0f, 1e10f};
    for (const float center_scale : scales) {
        for (const float size_scale : scales) {
            for (const float rotation_length : rotation_lengths) {
                for (int k = 0; k < 6; ++k) {
                    rect_pose p;
                    p.center = {random.uniform(-1.0f, 1.0f) * center_scale, random.uniform(-1.0f, 1.0f) * center_scale};
                    p.half_extents = {random.uniform(0.0f, 1.0f) * size_scale, random.uniform(0.0f, 1.0f) * size_scale};
                    if (k == 0) {
                        p.half_extents.y = 0.0f;
                    }
                    const float t = random.uniform(-1.0f, 1.0f);
                    p.rotation = {(1.0f - t * t) / (1.0f + t * t) * rotation_length,
                                  2.0f * t / (1.0f + t * t) * rotation_length};
                    if (k == 1) {
                        p.rotation = {rotation_length, 0.0f};
                    }
                    if (!std::isfinite(p.rotation.x) || (p.rotation.x == 0.0f && p.rotation.y == 0.0f)) {
                        continue;
                    }
                    poses.push_back(p);
                }
            }
        }
    }
    poses.push_back(rect_pose{{1.4e-45f, -1.4e-45f}, {1.4e-45f, 0.0f}, {1.0f, 0.0f}});
    poses.push_back(rect_pose{{0.0f, 0.0f}, {0.0f, 0.0f}, {0.6f, 0.8f}});
    return poses;
}

TEST(bounds_ref, pose_bounds_contain_every_exact_corner) {
    std::size_t checked = 0;
    for (const rect_pose& p : hard_poses()) {
        const box_bounds b = obbsat::ref::bounds_of(p);
        ASSERT_FALSE(std::isnan(b.lo_x) || std::isnan(b.lo_y) || std::isnan(b.hi_x) || std::isnan(b.hi_y));
        const exact_extent e = exact_extent_of(p);
        if (std::isfinite(b.lo_x)) {
            EXPECT_LE(exact(b.lo_x), e.lo_x) << checked;
        }
        if (std::isfinite(b.hi_x)) {
            EXPECT_GE(exact(b.hi_x), e.hi_x) << checked;
        }
        if (std::isfinite(b.lo_y)) {
            EXPECT_LE(exact(b.lo_y), e.lo_y) << checked;
        }
        if (std::isfinite(b.hi_y)) {
            EXPECT_GE(exact(b.hi_y), e.hi_y) << checked;
        }
        EXPECT_TRUE(b.lo_x != INFINITY && b.hi_x != -INFINITY && b.lo_y != INFINITY && b.hi_y != -INFINITY);
        ++checked;
    }
    EXPECT_GT(checked, 2000u);
}

TEST(bounds_ref, pose_bounds_are_within_the_contract_margin) {
    // Each bound is within (2^-21 + 2^-22)·(|c| + e) + 2^-139 of the exact
    // one, where the pose is finite enough that nothing overflows.
    for (const rect_pose& p : hard_poses()) {
        const box_bounds b = obbsat::ref::bounds_of(p);
        if (!std::isfinite(b.lo_x) || !std::isfinite(b.hi_x) || !std::isfinite(b.lo_y) || !std::isfinite(b.hi_y)) {
            continue;
        }
        const exact_extent e = exact_extent_of(p);
        const mpq_class ex = (e.hi_x - e.lo_x) / 2;
        const mpq_class ey = (e.hi_y - e.lo_y) / 2;
        const mpq_class slack(std::ldexp(1.0, -21) + std::ldexp(1.0, -22));
        const mpq_class tiny(std::ldexp(1.0, -139));
        const mpq_class allowed_x = slack * (abs(exact(p.center.x)) + ex) + tiny;
        const mpq_class allowed_y = slack * (abs(exact(p.center.y)) + ey) + tiny;
        EXPECT_LE(e.lo_x - exact(b.lo_x), allowed_x);
        EXPECT_LE(exact(b.hi_x) - e.hi_x, allowed_x);
        EXPECT_LE(e.lo_y - exact(b.lo_y), allowed_y);
        EXPECT_LE(exact(b.hi_y) - e.hi_y, allowed_y);
    }
}

TEST(bounds_ref, pose_bounds_overflow_to_infinity_never_to_nan) {
    const rect_pose huge{{3e38f, -3e38f}, {3e38f, 3e38f}, {1.0f, 1.0f}};
    const box_bounds b = obbsat::ref::bounds_of(huge);
    EXPECT_EQ(b.lo_x, -INFINITY);
    EXPECT_EQ(b.hi_x, INFINITY);
    EXPECT_EQ(b.lo_y, -INFINITY);
    EXPECT_EQ(b.hi_y, INFINITY);
}

TEST(bounds_ref, corner_bounds_are_the_corners_extremes) {
    const obbsat::rect r{{-1.0f, 2.0f}, {3.0f, 5.0f}, {4.0f, -1.0f}, {0.5f, -2.0f}};
    const box_bounds b = obbsat::ref::bounds_of(r);
    EXPECT_EQ(b.lo_x, -1.0f);
    EXPECT_EQ(b.hi_x, 4.0f);
    EXPECT_EQ(b.lo_y, -2.0f);
    EXPECT_EQ(b.hi_y, 5.0f);
}

TEST(bounds_ref, touching_bounds_overlap) {
    const box_bounds a{0.0f, 0.0f, 1.0f, 1.0f};
    EXPECT_TRUE(obbsat::ref::bounds_overlap(a, box_bounds{1.0f, 1.0f, 2.0f, 2.0f}));
    EXPECT_FALSE(obbsat::ref::bounds_overlap(a, box_bounds{std::nextafter(1.0f, 2.0f), 0.0f, 2.0f, 1.0f}));
    EXPECT_FALSE(obbsat::ref::bounds_overlap(a, box_bounds{0.0f, -2.0f, 1.0f, std::nextafter(0.0f, -1.0f)}));
}

}  // namespace
