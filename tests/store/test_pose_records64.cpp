// pose_records64 keeps every double exactly, refuses what is not a pose with a
// message naming the pose and the field, and stores nothing from a bad batch.
#include "test_support/refusal.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_records64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::rect_pose64;

const rect_pose64 footprint{{500000.123456789, 5712345.987654321}, {10.0000001, 4.9999999}, {0.8, 0.6}};

std::string message_of(const std::vector<rect_pose64>& poses) {
    return obbsat::test_support::refusal_of<obbsat::pose_records64>(poses);
}

TEST(pose_records64, keeps_every_double_exactly) {
    rect_pose64 near = footprint;
    near.center.x = std::nextafter(near.center.x, INFINITY);  // one ulp: lost in float32
    const obbsat::pose_records64 store(std::vector<rect_pose64>{footprint, near});
    ASSERT_EQ(store.size(), 2u);
    EXPECT_EQ(store[0].center.x, footprint.center.x);
    EXPECT_EQ(store[0].center.y, footprint.center.y);
    EXPECT_EQ(store[0].half_extents.x, footprint.half_extents.x);
    EXPECT_EQ(store[0].half_extents.y, footprint.half_extents.y);
    EXPECT_EQ(store[0].rotation.x, footprint.rotation.x);  // not normalised
    EXPECT_EQ(store[0].rotation.y, footprint.rotation.y);
    EXPECT_NE(store[1].center.x, store[0].center.x);
    EXPECT_EQ(store.at(1).center.x, near.center.x);
    // One record per cache line, the first on a 64-byte boundary.
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(store.data()) % 64, 0u);
    EXPECT_EQ(store.data()[obbsat::pose_records64::record_doubles], near.center.x);
    EXPECT_EQ(store.data()[6], 0.0);
}

TEST(pose_records64, zero_half_extents_are_a_segment_or_a_point) {
    rect_pose64 point = footprint;
    point.half_extents = {0.0, 0.0};
    obbsat::pose_records64 store;
    store.push_back(point);
    EXPECT_EQ(store.size(), 1u);
}

TEST(pose_records64, refuses_and_names_pose_and_field) {
    auto with = [](auto change) {
        std::vector<rect_pose64> poses{footprint, footprint, footprint};
        change(poses[2]);
        return poses;
    };
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.center.y = std::numeric_limits<double>::quiet_NaN(); })),
              "pose 2: cy is nan, not a finite number");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.rotation.x = -INFINITY; })),
              "pose 2: c is -inf, not a finite number");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.half_extents.y = -1.0; })),
              "pose 2: half extent hy is -1, negative");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.half_extents.x = -0.5; })),
              "pose 2: half extent hx is -0.5, negative");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.rotation = {0.0, -0.0}; })),
              "pose 2: rotation vector (c, s) is (0, 0)");
    EXPECT_EQ(message_of(with([](rect_pose64&) {})), "");
}

TEST(pose_records64, push_back_and_set_refuse_without_changing_the_store) {
    obbsat::pose_records64 store(std::vector<rect_pose64>{footprint});
    rect_pose64 bad = footprint;
    bad.half_extents.x = -2.0;
    EXPECT_THROW(store.push_back(bad), obbsat::invalid_input);
    EXPECT_THROW(store.set(0, bad), obbsat::invalid_input);
    EXPECT_THROW(store.set(1, footprint), obbsat::invalid_input);
    EXPECT_THROW(store.at(1), obbsat::invalid_input);
    ASSERT_EQ(store.size(), 1u);
    EXPECT_EQ(store[0].half_extents.x, footprint.half_extents.x);
    try {
        store.push_back(bad);
    } catch (const obbsat::invalid_input& e) {
        EXPECT_EQ(std::string(e.what()), "pose 1: half extent hx is -2, negative");
    }
}

TEST(pose_records64, require_valid_poses_names_the_first_bad_pose) {
    std::vector<rect_pose64> poses(5, footprint);
    poses[3].rotation = {0.0, 0.0};
    poses[4].center.x = INFINITY;
    try {
        obbsat::require_valid_poses(poses.data(), poses.size());
        FAIL() << "no error";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_EQ(std::string(e.what()), "pose 3: rotation vector (c, s) is (0, 0)");
    }
}

}  // namespace
