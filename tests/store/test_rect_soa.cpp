// rect_soa: construction, layout (alignment, padding), copies and moves,
// growth, bounds errors, and the finite-only invariant with its messages.
// Coordinates are compared exactly: rect_soa stores floats, it computes none.
// Only corners_of at angles other than 0 uses a tolerance (see there).
#include "test_support/float_text.hpp"
#include "test_support/rect_shapes.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/rect_soa.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::coord;
using obbsat::point;
using obbsat::pose;
using obbsat::rect;
using obbsat::rect_soa;
using obbsat::test_support::describe;

constexpr float nan_value = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_value = std::numeric_limits<float>::infinity();

/// A rectangle whose eight coordinates all differ and encode its index.
rect numbered_rect(std::size_t index) {
    const float base = static_cast<float>(index) * 8.0f;
    return rect{
        {base + 0, base + 1}, {base + 2, base + 3}, {base + 4, base + 5}, {base + 6, base + 7}};
}

std::vector<rect> numbered_rects(std::size_t count) {
    std::vector<rect> out;
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(numbered_rect(i));
    }
    return out;
}

bool same_rect(const rect& a, const rect& b) { return std::memcmp(&a, &b, sizeof(rect)) == 0; }

/// The coordinate `c` of `r`, in rect_soa's storage order.
float& coordinate(rect& r, unsigned c) {
    point* corners[4] = {&r.ul, &r.ur, &r.lr, &r.ll};
    return (c % 2 == 0) ? corners[c / 2]->x : corners[c / 2]->y;
}

testing::AssertionResult holds_exactly(const rect_soa& soa, const std::vector<rect>& expected) {
    if (soa.size() != expected.size()) {
        return testing::AssertionFailure()
               << "size " << soa.size() << ", expected " << expected.size();
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (!same_rect(soa[i], expected[i])) {
            return testing::AssertionFailure() << "rectangle " << i << " is " << describe(soa[i])
                                               << ", expected " << describe(expected[i]);
        }
    }
    return testing::AssertionSuccess();
}

testing::AssertionResult well_laid_out(const rect_soa& soa) {
    if (soa.capacity() % rect_soa::padding != 0 || soa.capacity() < soa.size()) {
        return testing::AssertionFailure()
               << "capacity " << soa.capacity() << " for size " << soa.size();
    }
    if (soa.capacity() == 0) {
        return testing::AssertionSuccess();
    }
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        const float* values = soa.data(coord(c));
        if (reinterpret_cast<std::uintptr_t>(values) % rect_soa::alignment != 0) {
            return testing::AssertionFailure() << obbsat::coord_name(coord(c)) << " is not aligned";
        }
        for (std::size_t i = soa.size(); i < soa.capacity(); ++i) {
            if (values[i] != 0.0f || std::signbit(values[i])) {
                return testing::AssertionFailure() << obbsat::coord_name(coord(c))
                                                   << " padding entry " << i << " is " << values[i];
            }
        }
    }
    return testing::AssertionSuccess();
}

TEST(rect_soa, default_is_empty) {
    const rect_soa soa;
    EXPECT_EQ(soa.size(), 0u);
    EXPECT_TRUE(soa.empty());
    EXPECT_TRUE(well_laid_out(soa));
}

TEST(rect_soa, stores_each_coordinate_in_its_own_array) {
    const std::vector<rect> rects = numbered_rects(5);
    const rect_soa soa(rects);
    ASSERT_TRUE(holds_exactly(soa, rects));
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        for (std::size_t i = 0; i < rects.size(); ++i) {
            EXPECT_EQ(soa.data(coord(c))[i], static_cast<float>(8 * i + c))
                << obbsat::coord_name(coord(c)) << " of rectangle " << i;
        }
    }
}

TEST(rect_soa, coordinate_names_follow_storage_order) {
    const char* expected[] = {"ulx", "uly", "urx", "ury", "lrx", "lry", "llx", "lly"};
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        EXPECT_STREQ(obbsat::coord_name(coord(c)), expected[c]);
    }
}

TEST(rect_soa, pointer_and_vector_constructors_agree_and_lay_out_well) {
    for (const std::size_t count : {0u, 1u, 15u, 16u, 17u, 31u, 32u, 33u, 100u, 1000u}) {
        SCOPED_TRACE("count " + std::to_string(count));
        const std::vector<rect> rects = numbered_rects(count);
        const rect_soa from_vector(rects);
        const rect_soa from_pointer(rects.data(), rects.size());
        EXPECT_TRUE(holds_exactly(from_vector, rects));
        EXPECT_TRUE(holds_exactly(from_pointer, rects));
        EXPECT_TRUE(well_laid_out(from_vector));
        EXPECT_TRUE(well_laid_out(from_pointer));
    }
}

TEST(rect_soa, keeps_every_finite_value_bit_for_bit) {
    const float values[] = {-0.0f,
                            0.0f,
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::max(),
                            -std::numeric_limits<float>::max(),
                            0x1.fffffep-1f};
    rect r{};
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        coordinate(r, c) = values[c];
    }
    const rect_soa soa(std::vector<rect>{r, obbsat::test_support::relabelled(r)});
    EXPECT_TRUE(holds_exactly(soa, {r, obbsat::test_support::relabelled(r)}));
}

TEST(rect_soa, push_back_grows_in_padded_steps_and_keeps_contents) {
    rect_soa soa;
    std::vector<rect> expected;
    for (std::size_t i = 0; i < 300; ++i) {
        soa.push_back(numbered_rect(i));
        expected.push_back(numbered_rect(i));
        ASSERT_EQ(soa.size(), i + 1);
        ASSERT_TRUE(well_laid_out(soa)) << "after " << i + 1 << " push_backs";
    }
    EXPECT_TRUE(holds_exactly(soa, expected));
}

TEST(rect_soa, reserve_makes_room_without_moving_on_push_back) {
    rect_soa soa;
    soa.reserve(100);
    EXPECT_GE(soa.capacity(), 100u);
    EXPECT_TRUE(well_laid_out(soa));
    const float* before = soa.data(coord::ulx);
    for (std::size_t i = 0; i < 100; ++i) {
        soa.push_back(numbered_rect(i));
    }
    EXPECT_EQ(soa.data(coord::ulx), before);
    EXPECT_TRUE(holds_exactly(soa, numbered_rects(100)));
    // Reserving less than the capacity changes nothing.
    soa.reserve(10);
    EXPECT_EQ(soa.data(coord::ulx), before);
    EXPECT_TRUE(holds_exactly(soa, numbered_rects(100)));
}

TEST(rect_soa, clear_empties_and_zeroes_what_was_stored) {
    rect_soa soa(numbered_rects(40));
    const std::size_t capacity = soa.capacity();
    soa.clear();
    EXPECT_TRUE(soa.empty());
    EXPECT_EQ(soa.capacity(), capacity);
    EXPECT_TRUE(well_laid_out(soa));  // every entry is padding again, so zero
    soa.push_back(numbered_rect(3));
    EXPECT_TRUE(holds_exactly(soa, {numbered_rect(3)}));
    EXPECT_TRUE(well_laid_out(soa));
}

TEST(rect_soa, copy_is_deep_and_equal) {
    rect_soa original(numbered_rects(37));
    const rect_soa copy(original);
    EXPECT_TRUE(holds_exactly(copy, numbered_rects(37)));
    EXPECT_TRUE(well_laid_out(copy));
    EXPECT_NE(copy.data(coord::ulx), original.data(coord::ulx));
    original.set(0, numbered_rect(99));
    EXPECT_TRUE(same_rect(copy[0], numbered_rect(0)));

    rect_soa assigned(numbered_rects(3));
    assigned = original;
    EXPECT_TRUE(holds_exactly(assigned, [&] {
        auto r = numbered_rects(37);
        r[0] = numbered_rect(99);
        return r;
    }()));
    EXPECT_TRUE(well_laid_out(assigned));
    // Self-assignment keeps the contents.
    const rect_soa& same = assigned;
    assigned = same;
    EXPECT_EQ(assigned.size(), 37u);
    EXPECT_TRUE(same_rect(assigned[0], numbered_rect(99)));
}

TEST(rect_soa, copy_of_empty_is_empty) {
    const rect_soa empty;
    const rect_soa copy(empty);
    EXPECT_TRUE(copy.empty());
    rect_soa assigned(numbered_rects(5));
    assigned = empty;
    EXPECT_TRUE(assigned.empty());
    EXPECT_TRUE(well_laid_out(assigned));
}

TEST(rect_soa, move_takes_the_storage_and_leaves_an_empty_usable_source) {
    rect_soa source(numbered_rects(20));
    const float* storage = source.data(coord::ulx);
    rect_soa moved(std::move(source));
    EXPECT_EQ(moved.data(coord::ulx), storage);
    EXPECT_TRUE(holds_exactly(moved, numbered_rects(20)));
    // Like a moved-from std::vector, the source is left empty and usable.
    EXPECT_TRUE(source.empty());
    source.push_back(numbered_rect(7));
    EXPECT_TRUE(holds_exactly(source, {numbered_rect(7)}));
    EXPECT_TRUE(well_laid_out(source));

    rect_soa target(numbered_rects(2));
    target = std::move(moved);
    EXPECT_EQ(target.data(coord::ulx), storage);
    EXPECT_TRUE(holds_exactly(target, numbered_rects(20)));
    EXPECT_TRUE(moved.empty());
}

TEST(rect_soa, set_replaces_one_rectangle) {
    rect_soa soa(numbered_rects(4));
    soa.set(2, numbered_rect(50));
    std::vector<rect> expected = numbered_rects(4);
    expected[2] = numbered_rect(50);
    EXPECT_TRUE(holds_exactly(soa, expected));
    EXPECT_TRUE(same_rect(soa.at(2), numbered_rect(50)));
}

TEST(rect_soa, at_and_set_reject_an_index_past_the_end_naming_it) {
    rect_soa soa(numbered_rects(3));
    for (const std::size_t bad : {std::size_t{3}, std::size_t{4}, std::size_t{1000000}}) {
        try {
            (void)soa.at(bad);
            ADD_FAILURE() << "at(" << bad << ") did not throw";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("rectangle " + std::to_string(bad)),
                      std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("size 3"), std::string::npos) << e.what();
        }
        EXPECT_THROW(soa.set(bad, numbered_rect(9)), obbsat::invalid_input);
    }
    EXPECT_TRUE(holds_exactly(soa, numbered_rects(3)));
    const rect_soa empty;
    EXPECT_THROW((void)empty.at(0), obbsat::invalid_input);
}

// Every non-finite value in every coordinate, through every way in: the error
// names the rectangle and the coordinate, and nothing changes.
TEST(rect_soa, rejects_non_finite_coordinates_naming_rectangle_and_coordinate) {
    const float bad_values[] = {nan_value, inf_value, -inf_value};
    for (const float bad : bad_values) {
        for (unsigned c = 0; c < obbsat::coord_count; ++c) {
            const std::string name = obbsat::coord_name(coord(c));
            SCOPED_TRACE(name + " = " + std::to_string(bad));
            rect poisoned = numbered_rect(5);
            coordinate(poisoned, c) = bad;
            auto expect_message = [&](const obbsat::invalid_input& e, std::size_t index) {
                const std::string what = e.what();
                EXPECT_NE(what.find("rectangle " + std::to_string(index)), std::string::npos)
                    << what;
                EXPECT_NE(what.find(name), std::string::npos) << what;
                EXPECT_NE(what.find("not finite"), std::string::npos) << what;
            };

            // Constructors: the whole batch is refused.
            std::vector<rect> rects = numbered_rects(7);
            rects[5] = poisoned;
            try {
                const rect_soa soa(rects);
                ADD_FAILURE() << "constructor accepted " << describe(poisoned);
            } catch (const obbsat::invalid_input& e) {
                expect_message(e, 5);
            }
            EXPECT_THROW((void)rect_soa(rects.data(), rects.size()), obbsat::invalid_input);

            // push_back: the size and the stored rectangles stay as they were,
            // at a capacity boundary (16 stored) and inside one (5 stored).
            for (const std::size_t stored : {std::size_t{16}, std::size_t{5}}) {
                rect_soa soa(numbered_rects(stored));
                try {
                    soa.push_back(poisoned);
                    ADD_FAILURE() << "push_back accepted " << describe(poisoned);
                } catch (const obbsat::invalid_input& e) {
                    expect_message(e, stored);
                }
                EXPECT_TRUE(holds_exactly(soa, numbered_rects(stored)));
                EXPECT_TRUE(well_laid_out(soa));
            }

            // set: the old rectangle stays.
            rect_soa soa(numbered_rects(7));
            try {
                soa.set(2, poisoned);
                ADD_FAILURE() << "set accepted " << describe(poisoned);
            } catch (const obbsat::invalid_input& e) {
                expect_message(e, 2);
            }
            EXPECT_TRUE(holds_exactly(soa, numbered_rects(7)));
            EXPECT_TRUE(well_laid_out(soa));
        }
    }
}

TEST(rect_soa, from_coordinate_arrays_reads_eight_arrays_in_coord_order) {
    const std::vector<rect> rects = numbered_rects(21);
    std::vector<float> arrays[obbsat::coord_count];
    for (const rect& r : rects) {
        rect copy = r;
        for (unsigned c = 0; c < obbsat::coord_count; ++c) {
            arrays[c].push_back(coordinate(copy, c));
        }
    }
    const float* pointers[obbsat::coord_count];
    for (unsigned c = 0; c < obbsat::coord_count; ++c) {
        pointers[c] = arrays[c].data();
    }
    const rect_soa soa = rect_soa::from_coordinate_arrays(pointers, rects.size());
    EXPECT_TRUE(holds_exactly(soa, rects));
    EXPECT_TRUE(well_laid_out(soa));
    EXPECT_TRUE(rect_soa::from_coordinate_arrays(pointers, 0).empty());
    // The same finite-only rule, naming the rectangle and the coordinate.
    arrays[static_cast<unsigned>(coord::lry)][13] = nan_value;
    try {
        (void)rect_soa::from_coordinate_arrays(pointers, rects.size());
        ADD_FAILURE() << "accepted a NaN";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("rectangle 13"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("lry"), std::string::npos) << e.what();
    }
}

TEST(rect_soa, from_poses_stores_corners_of_each_pose) {
    const std::vector<pose> poses = {
        {{1, 2}, {3, 4}, 0.0f}, {{-5, 7}, {0.5f, 2}, 0.7f}, {{0, 0}, {1, 1}, -2.0f}};
    const rect_soa soa = rect_soa::from_poses(poses);
    ASSERT_EQ(soa.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        EXPECT_TRUE(same_rect(soa[i], obbsat::corners_of(poses[i]))) << "pose " << i;
    }
    const rect_soa from_pointer = rect_soa::from_poses(poses.data(), poses.size());
    EXPECT_TRUE(holds_exactly(from_pointer, {soa[0], soa[1], soa[2]}));
    EXPECT_TRUE(well_laid_out(soa));
}

TEST(rect_soa, from_poses_rejects_poses_whose_corners_are_not_finite) {
    const float huge = std::numeric_limits<float>::max();
    const std::pair<const char*, pose> bad_poses[] = {
        {"NaN center", {{nan_value, 0}, {1, 1}, 0.0f}},
        {"infinite half extent", {{0, 0}, {inf_value, 1}, 0.0f}},
        {"NaN angle", {{0, 0}, {1, 1}, nan_value}},
        {"corners overflow float", {{huge, huge}, {huge, huge}, 0.0f}},
    };
    for (const auto& [what, bad] : bad_poses) {
        SCOPED_TRACE(what);
        std::vector<pose> poses(4, pose{{0, 0}, {1, 1}, 0.0f});
        poses[3] = bad;
        try {
            (void)rect_soa::from_poses(poses);
            ADD_FAILURE() << "accepted";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("rectangle 3"), std::string::npos) << e.what();
        }
    }
}

TEST(corners_of, angle_zero_is_exact) {
    // cos(0) = 1 and sin(0) = 0 exactly, so the corners are exact sums.
    const rect r = obbsat::corners_of(pose{{1, 2}, {3, 4}, 0.0f});
    EXPECT_TRUE(same_rect(r, rect{{-2, 6}, {4, 6}, {4, -2}, {-2, -2}})) << describe(r);
    // Rounded once, from double: 1e8 + 1 is not a float, 1e8 is the nearest.
    const rect far = obbsat::corners_of(pose{{1.0e8f, 0}, {1, 0.5f}, 0.0f});
    EXPECT_EQ(far.ur.x, 1.0e8f);
    EXPECT_EQ(far.ur.y, 0.5f);
}

TEST(corners_of, quarter_and_half_turns_within_rounding) {
    // The only tolerance in this file: float(pi / 2) is not pi / 2, and cos
    // and sin of it are not exactly 0 and 1, so corners are off by ~1e-7
    // times the half extents. 1e-5 is far above that and far below 1.
    const float tolerance = 1.0e-5f;
    auto expect_near = [&](const rect& got, const rect& want) {
        const point g[4] = {got.ul, got.ur, got.lr, got.ll};
        const point w[4] = {want.ul, want.ur, want.lr, want.ll};
        for (unsigned k = 0; k < 4; ++k) {
            EXPECT_NEAR(g[k].x, w[k].x, tolerance) << "corner " << k << ": " << describe(got);
            EXPECT_NEAR(g[k].y, w[k].y, tolerance) << "corner " << k << ": " << describe(got);
        }
    };
    const float quarter = 1.57079632679f;
    // Counter-clockwise by a quarter: local (x, y) goes to (-y, x).
    expect_near(obbsat::corners_of(pose{{1, 2}, {3, 4}, quarter}),
                rect{{-3, -1}, {-3, 5}, {5, 5}, {5, -1}});
    expect_near(obbsat::corners_of(pose{{1, 2}, {3, 4}, 2.0f * quarter}),
                rect{{4, -2}, {-2, -2}, {-2, 6}, {4, 6}});
    expect_near(obbsat::corners_of(pose{{1, 2}, {3, 4}, -quarter}),
                rect{{5, 5}, {5, -1}, {-3, -1}, {-3, 5}});
}

}  // namespace
