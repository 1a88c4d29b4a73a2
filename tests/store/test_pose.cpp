// pose_of recovers the pose a rectangle's corners came from, to within the
// rounding of corners_of (which uses cos and sin, hence the tolerances).
#include <obbsat/pose.hpp>

#include <gtest/gtest.h>

namespace {

TEST(pose, pose_of_inverts_corners_of) {
    for (const float angle : {0.0f, 0.3f, 1.2f, -2.5f, 3.0f}) {
        const obbsat::pose p{{12.5f, -3.25f}, {4.0f, 0.75f}, angle};
        const obbsat::pose q = obbsat::pose_of(obbsat::corners_of(p));
        EXPECT_NEAR(q.center.x, p.center.x, 1e-5f);
        EXPECT_NEAR(q.center.y, p.center.y, 1e-5f);
        EXPECT_NEAR(q.half_extents.x, p.half_extents.x, 1e-5f);
        EXPECT_NEAR(q.half_extents.y, p.half_extents.y, 1e-5f);
        EXPECT_NEAR(q.angle, p.angle, 1e-5f) << "angle " << angle;
    }
}

TEST(pose, axis_aligned_corners_give_exact_pose) {
    const obbsat::rect r{{0, 2}, {6, 2}, {6, 0}, {0, 0}};
    const obbsat::pose p = obbsat::pose_of(r);
    EXPECT_EQ(p.center.x, 3.0f);
    EXPECT_EQ(p.center.y, 1.0f);
    EXPECT_EQ(p.half_extents.x, 3.0f);
    EXPECT_EQ(p.half_extents.y, 1.0f);
    EXPECT_EQ(p.angle, 0.0f);
}

}  // namespace
