// rect_records64 keeps every double corner exactly, refuses a non-finite
// coordinate naming the rectangle and the coordinate, and stores nothing from
// a bad batch.
#include <obbsat/error.hpp>
#include <obbsat/rect_records64.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::rect64;

const rect64 footprint{{500000.125, 5712350.5}, {500020.125, 5712350.5}, {500020.125, 5712340.5},
                       {500000.125, 5712340.5}};

TEST(rect_records64, keeps_every_double_exactly) {
    rect64 near = footprint;
    near.ur.x = std::nextafter(near.ur.x, INFINITY);
    const obbsat::rect_records64 store(std::vector<rect64>{footprint, near});
    ASSERT_EQ(store.size(), 2u);
    EXPECT_EQ(store[1].ur.x, near.ur.x);
    EXPECT_NE(store[1].ur.x, store[0].ur.x);
    EXPECT_EQ(store.at(0).ll.y, footprint.ll.y);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(store.data()) % 64, 0u);
}

TEST(rect_records64, refuses_a_non_finite_coordinate_and_stores_nothing) {
    std::vector<rect64> rects(4, footprint);
    rects[2].lr.y = NAN;
    try {
        obbsat::rect_records64 store(rects);
        FAIL() << "no error";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_EQ(std::string(e.what()), "rectangle 2: coordinate lry is nan, not a finite number");
    }
    obbsat::rect_records64 store(std::vector<rect64>{footprint});
    rect64 bad = footprint;
    bad.ul.x = -INFINITY;
    EXPECT_THROW(store.push_back(bad), obbsat::invalid_input);
    EXPECT_THROW(store.set(0, bad), obbsat::invalid_input);
    EXPECT_THROW(store.set(3, footprint), obbsat::invalid_input);
    ASSERT_EQ(store.size(), 1u);
    EXPECT_EQ(store[0].ul.x, footprint.ul.x);
}

}  // namespace
