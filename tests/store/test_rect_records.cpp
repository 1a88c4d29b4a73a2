// rect_records: packed 32-byte records, their alignment (64 bytes, 2 MiB for
// large blocks), growth, copies, bounds errors and the finite-only invariant
// with its messages. Coordinates are compared exactly: the store computes none.
#include "test_support/float_text.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::point;
using obbsat::pose;
using obbsat::rect;
using obbsat::rect_records;
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

/// The coordinate `c` of `r`, in record order ulx, uly, urx, ury, lrx, lry, llx, lly.
float& coordinate(rect& r, unsigned c) {
    point* corners[4] = {&r.ul, &r.ur, &r.lr, &r.ll};
    return (c % 2 == 0) ? corners[c / 2]->x : corners[c / 2]->y;
}

bool aligned_to(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

testing::AssertionResult holds_exactly(const rect_records& records,
                                       const std::vector<rect>& expected) {
    if (records.size() != expected.size()) {
        return testing::AssertionFailure()
               << "size " << records.size() << ", expected " << expected.size();
    }
    if (!expected.empty() && !aligned_to(records.data(), 64)) {
        return testing::AssertionFailure() << "records are not on a 64-byte boundary";
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        // The records are packed: record i is the 32 bytes at data() + i.
        if (std::memcmp(records.data() + i, &expected[i], sizeof(rect)) != 0 ||
            std::memcmp(&records[i], &expected[i], sizeof(rect)) != 0) {
            return testing::AssertionFailure() << "record " << i << " is " << describe(records[i])
                                               << ", expected " << describe(expected[i]);
        }
    }
    return testing::AssertionSuccess();
}

TEST(rect_records, a_record_is_the_32_bytes_of_a_rect) {
    static_assert(sizeof(rect) == 32, "a record is eight packed floats");
    const rect r = numbered_rect(1);
    const float expected[8] = {8, 9, 10, 11, 12, 13, 14, 15};
    EXPECT_EQ(std::memcmp(&r, expected, sizeof expected), 0);
}

TEST(rect_records, default_is_empty) {
    const rect_records records;
    EXPECT_EQ(records.size(), 0u);
    EXPECT_TRUE(records.empty());
}

TEST(rect_records, pointer_and_vector_constructors_store_packed_aligned_records) {
    for (const std::size_t count : {0u, 1u, 2u, 3u, 17u, 1000u}) {
        SCOPED_TRACE("count " + std::to_string(count));
        const std::vector<rect> rects = numbered_rects(count);
        EXPECT_TRUE(holds_exactly(rect_records(rects), rects));
        EXPECT_TRUE(holds_exactly(rect_records(rects.data(), rects.size()), rects));
    }
}

TEST(rect_records, from_a_rect_soa_holds_the_same_rectangles) {
    for (const std::size_t count : {0u, 1u, 16u, 33u}) {
        const std::vector<rect> rects = numbered_rects(count);
        EXPECT_TRUE(holds_exactly(rect_records(obbsat::rect_soa(rects)), rects)) << count;
    }
}

TEST(rect_records, push_back_grows_and_keeps_contents_and_alignment) {
    rect_records records;
    std::vector<rect> expected;
    for (std::size_t i = 0; i < 300; ++i) {
        records.push_back(numbered_rect(i));
        expected.push_back(numbered_rect(i));
        ASSERT_TRUE(holds_exactly(records, expected)) << "after " << i + 1 << " push_backs";
    }
}

TEST(rect_records, memory_is_64_byte_aligned_and_large_blocks_2_mib_aligned) {
    for (const std::size_t bytes :
         {std::size_t{32}, std::size_t{64 * 1024}, std::size_t{3} << 20}) {
        void* block = obbsat::allocate_record_memory(bytes);
        EXPECT_TRUE(aligned_to(block, 64)) << bytes << " bytes";
        std::memset(block, 0x5a, bytes);  // the whole block is usable
        obbsat::release_record_memory(block, bytes);
    }
    for (const std::size_t bytes : {std::size_t{4} << 20, std::size_t{9} << 20}) {
        void* block = obbsat::allocate_record_memory(bytes);
        EXPECT_TRUE(aligned_to(block, std::size_t{2} << 20)) << bytes << " bytes";
        std::memset(block, 0x5a, bytes);
        obbsat::release_record_memory(block, bytes);
    }
    // A store of 4 MiB of records lies in such a block.
    rect_records large;
    large.reserve(std::size_t{1} << 17);
    large.push_back(numbered_rect(0));
    EXPECT_TRUE(aligned_to(large.data(), std::size_t{2} << 20));
}

TEST(rect_records, copy_is_deep_and_move_takes_the_records) {
    rect_records original(numbered_rects(37));
    const rect_records copy(original);
    EXPECT_TRUE(holds_exactly(copy, numbered_rects(37)));
    EXPECT_NE(copy.data(), original.data());
    original.set(0, numbered_rect(99));
    EXPECT_TRUE(holds_exactly(copy, numbered_rects(37)));

    const rect* storage = original.data();
    rect_records moved(std::move(original));
    EXPECT_EQ(moved.data(), storage);
    EXPECT_EQ(moved.size(), 37u);
    rect_records assigned;
    assigned = moved;
    EXPECT_TRUE(holds_exactly(assigned, [] {
        auto r = numbered_rects(37);
        r[0] = numbered_rect(99);
        return r;
    }()));
}

TEST(rect_records, set_at_and_clear) {
    rect_records records(numbered_rects(4));
    records.set(2, numbered_rect(50));
    std::vector<rect> expected = numbered_rects(4);
    expected[2] = numbered_rect(50);
    EXPECT_TRUE(holds_exactly(records, expected));
    EXPECT_EQ(std::memcmp(&records.at(2), &expected[2], sizeof(rect)), 0);
    records.clear();
    EXPECT_TRUE(records.empty());
    records.push_back(numbered_rect(3));
    EXPECT_TRUE(holds_exactly(records, {numbered_rect(3)}));
}

TEST(rect_records, at_and_set_reject_an_index_past_the_end_naming_it) {
    rect_records records(numbered_rects(3));
    for (const std::size_t bad : {std::size_t{3}, std::size_t{4}, std::size_t{1000000}}) {
        try {
            (void)records.at(bad);
            ADD_FAILURE() << "at(" << bad << ") did not throw";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("rectangle " + std::to_string(bad)),
                      std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find("size 3"), std::string::npos) << e.what();
        }
        EXPECT_THROW(records.set(bad, numbered_rect(9)), obbsat::invalid_input);
    }
    EXPECT_TRUE(holds_exactly(records, numbered_rects(3)));
    EXPECT_THROW((void)rect_records().at(0), obbsat::invalid_input);
}

// Every non-finite value in every coordinate, through every way in: the error
// names the rectangle and the coordinate, and nothing changes.
TEST(rect_records, rejects_non_finite_coordinates_naming_rectangle_and_coordinate) {
    for (const float bad : {nan_value, inf_value, -inf_value}) {
        for (unsigned c = 0; c < obbsat::coord_count; ++c) {
            const std::string name = obbsat::coord_name(obbsat::coord(c));
            SCOPED_TRACE(name + " = " + std::to_string(bad));
            rect poisoned = numbered_rect(5);
            coordinate(poisoned, c) = bad;
            auto expect_message = [&](const obbsat::invalid_input& e, std::size_t index) {
                const std::string what = e.what();
                EXPECT_NE(what.find("rectangle " + std::to_string(index)), std::string::npos)
                    << what;
                EXPECT_NE(what.find("coordinate " + name), std::string::npos) << what;
                EXPECT_NE(what.find("not finite"), std::string::npos) << what;
            };

            std::vector<rect> rects = numbered_rects(7);
            rects[5] = poisoned;
            try {
                const rect_records records(rects);
                ADD_FAILURE() << "constructor accepted " << describe(poisoned);
            } catch (const obbsat::invalid_input& e) {
                expect_message(e, 5);
            }
            EXPECT_THROW((void)rect_records(rects.data(), rects.size()), obbsat::invalid_input);

            rect_records records(numbered_rects(7));
            try {
                records.push_back(poisoned);
                ADD_FAILURE() << "push_back accepted " << describe(poisoned);
            } catch (const obbsat::invalid_input& e) {
                expect_message(e, 7);
            }
            EXPECT_TRUE(holds_exactly(records, numbered_rects(7)));
            try {
                records.set(2, poisoned);
                ADD_FAILURE() << "set accepted " << describe(poisoned);
            } catch (const obbsat::invalid_input& e) {
                expect_message(e, 2);
            }
            EXPECT_TRUE(holds_exactly(records, numbered_rects(7)));
        }
    }
}

TEST(rect_records, from_poses_stores_corners_of_each_pose_like_rect_soa) {
    const std::vector<pose> poses = {
        {{1, 2}, {3, 4}, 0.0f}, {{-5, 7}, {0.5f, 2}, 0.7f}, {{0, 0}, {1, 1}, -2.0f}};
    const rect_records records = rect_records::from_poses(poses);
    const obbsat::rect_soa soa = obbsat::rect_soa::from_poses(poses);
    std::vector<rect> expected;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        expected.push_back(obbsat::corners_of(poses[i]));
        const rect from_soa = soa[i];
        EXPECT_EQ(std::memcmp(&expected[i], &from_soa, sizeof(rect)), 0) << "pose " << i;
    }
    EXPECT_TRUE(holds_exactly(records, expected));
    EXPECT_TRUE(holds_exactly(rect_records::from_poses(poses.data(), poses.size()), expected));

    std::vector<pose> bad = poses;
    bad[1].center.y = nan_value;
    try {
        (void)rect_records::from_poses(bad);
        ADD_FAILURE() << "accepted a NaN center";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("rectangle 1"), std::string::npos) << e.what();
    }
}

}  // namespace
