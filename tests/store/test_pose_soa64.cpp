// pose_soa64 keeps every double exactly in six aligned arrays, refuses what is
// not a pose with a message naming the pose and the field, and stores nothing
// from a bad batch or a refused push_back or set.
#include "test_support/refusal.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_soa64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::pose_field;
using obbsat::rect_pose64;

const rect_pose64 footprint{{500000.123456789, 5712345.987654321}, {10.0000001, 4.9999999}, {0.8, 0.6}};

std::string message_of(const std::vector<rect_pose64>& poses) {
    return obbsat::test_support::refusal_of<obbsat::pose_soa64>(poses);
}

TEST(pose_soa64, keeps_every_double_exactly_one_array_per_field) {
    rect_pose64 near = footprint;
    near.center.x = std::nextafter(near.center.x, INFINITY);  // one ulp: lost in float32
    near.rotation = {3.0, -4.0};                               // not normalised
    const obbsat::pose_soa64 store(std::vector<rect_pose64>{footprint, near});
    ASSERT_EQ(store.size(), 2u);
    EXPECT_FALSE(store.empty());
    const pose_field fields[] = {pose_field::cx, pose_field::cy, pose_field::hx,
                                 pose_field::hy, pose_field::c,  pose_field::s};
    for (const pose_field f : fields) {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(store.data(f)) % 64, 0u);
    }
    EXPECT_EQ(store.data(pose_field::cx)[1], near.center.x);
    EXPECT_NE(store.data(pose_field::cx)[1], store.data(pose_field::cx)[0]);
    EXPECT_EQ(store.data(pose_field::cy)[0], footprint.center.y);
    EXPECT_EQ(store.data(pose_field::hx)[0], footprint.half_extents.x);
    EXPECT_EQ(store.data(pose_field::hy)[0], footprint.half_extents.y);
    EXPECT_EQ(store.data(pose_field::c)[1], 3.0);
    EXPECT_EQ(store.data(pose_field::s)[1], -4.0);
    const rect_pose64 back = store.at(1);
    EXPECT_EQ(back.center.x, near.center.x);
    EXPECT_EQ(back.rotation.y, -4.0);
}

TEST(pose_soa64, copies_a_record_store_as_it_is) {
    std::vector<rect_pose64> poses(37, footprint);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        poses[i].center.x += static_cast<double>(i) * 0.001;
        poses[i].rotation.y = -0.25 * static_cast<double>(i);
    }
    const obbsat::pose_records64 records(poses);
    const obbsat::pose_soa64 store(records);
    ASSERT_EQ(store.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        EXPECT_EQ(store[i].center.x, poses[i].center.x) << i;
        EXPECT_EQ(store[i].rotation.y, poses[i].rotation.y) << i;
    }
}

TEST(pose_soa64, refuses_and_names_pose_and_field) {
    auto with = [](auto change) {
        std::vector<rect_pose64> poses{footprint, footprint, footprint};
        change(poses[2]);
        return poses;
    };
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.center.y = std::numeric_limits<double>::quiet_NaN(); })),
              "pose 2: cy is nan, not a finite number");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.rotation.y = INFINITY; })),
              "pose 2: s is inf, not a finite number");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.half_extents.y = -1.0; })),
              "pose 2: half extent hy is -1, negative");
    EXPECT_EQ(message_of(with([](rect_pose64& p) { p.rotation = {0.0, -0.0}; })),
              "pose 2: rotation vector (c, s) is (0, 0)");
    EXPECT_EQ(message_of(with([](rect_pose64&) {})), "");
}

TEST(pose_soa64, push_back_and_set_refuse_without_changing_the_store) {
    obbsat::pose_soa64 store(std::vector<rect_pose64>{footprint});
    rect_pose64 bad = footprint;
    bad.center.x = -INFINITY;
    EXPECT_THROW(store.set(0, bad), obbsat::invalid_input);
    EXPECT_THROW(store.set(1, footprint), obbsat::invalid_input);
    EXPECT_THROW(store.at(1), obbsat::invalid_input);
    try {
        store.push_back(bad);
        FAIL() << "no error";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_EQ(std::string(e.what()), "pose 1: cx is -inf, not a finite number");
    }
    ASSERT_EQ(store.size(), 1u);
    EXPECT_EQ(store[0].center.x, footprint.center.x);
    rect_pose64 moved = footprint;
    moved.center.y = 1.5;
    store.set(0, moved);
    store.push_back(footprint);
    EXPECT_EQ(store[0].center.y, 1.5);
    EXPECT_EQ(store.size(), 2u);
    store.clear();
    EXPECT_TRUE(store.empty());
}

}  // namespace
