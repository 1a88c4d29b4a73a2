// pair_blocks against a plain vector of the same pairs: appends that cross
// blocks, rooms only partly used, reuse after clear(), and blocks that grow.
#include "scene/pair_blocks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

std::vector<obbsat::pair_index> flattened(const obbsat::detail::pair_blocks& blocks) {
    std::vector<obbsat::pair_index> out;
    for (const auto& span : blocks.spans()) {
        EXPECT_GT(span.size, 0u);
        out.insert(out.end(), span.data, span.data + span.size);
    }
    return out;
}

void expect_same(const std::vector<obbsat::pair_index>& got, const std::vector<obbsat::pair_index>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        ASSERT_TRUE(got[i].a == want[i].a && got[i].b == want[i].b) << "pair " << i;
    }
}

}  // namespace

TEST(pair_blocks, holds_what_was_added_in_order_across_blocks_and_after_clear) {
    using obbsat::detail::pair_blocks;
    pair_blocks blocks;
    EXPECT_TRUE(blocks.empty());
    EXPECT_TRUE(blocks.spans().empty());
    for (int round = 0; round < 2; ++round) {  // the second round reuses the blocks
        std::vector<obbsat::pair_index> want;
        std::uint32_t next = static_cast<std::uint32_t>(round) * 1000000u;
        // Rooms of 2048 with 0 to 2048 of them used: about 1.6M pairs, five
        // blocks and a part of a sixth.
        for (std::size_t step = 0; step < 1600; ++step) {
            const std::size_t room = 2048;
            const std::size_t used = (step * 977) % (room + 1);
            obbsat::pair_index* out = blocks.room(room);
            for (std::size_t i = 0; i < room; ++i) {
                out[i] = {next + static_cast<std::uint32_t>(i), 7};  // all written, `used` kept
            }
            for (std::size_t i = 0; i < used; ++i) {
                want.push_back(out[i]);
            }
            blocks.add(used);
            next += static_cast<std::uint32_t>(room);
        }
        ASSERT_GT(want.size(), 3 * pair_blocks::block_pairs);
        EXPECT_EQ(blocks.size(), want.size());
        EXPECT_GE(blocks.spans().size(), 6u);
        expect_same(flattened(blocks), want);
        blocks.clear();
        EXPECT_TRUE(blocks.empty());
        EXPECT_TRUE(blocks.spans().empty());
    }
    // A whole block in one room, then one more pair.
    obbsat::pair_index* out = blocks.room(pair_blocks::block_pairs);
    for (std::size_t i = 0; i < pair_blocks::block_pairs; ++i) {
        out[i] = {static_cast<std::uint32_t>(i), 1};
    }
    blocks.add(pair_blocks::block_pairs);
    blocks.room(1)[0] = {5, 5};
    blocks.add(1);
    const auto spans = blocks.spans();
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].size, pair_blocks::block_pairs);
    EXPECT_EQ(spans[1].size, 1u);
    EXPECT_EQ(spans[1].data[0].a, 5u);
}

TEST(pair_blocks, grow_from_the_first_block_to_four_mebibytes) {
    using obbsat::detail::pair_blocks;
    EXPECT_EQ(pair_blocks::pairs_of_block(0), pair_blocks::block_pairs);
    EXPECT_EQ(pair_blocks::pairs_of_block(1), 2 * pair_blocks::block_pairs);
    EXPECT_EQ(pair_blocks::pairs_of_block(3) * sizeof(obbsat::pair_index), std::size_t{4} << 20);
    EXPECT_EQ(pair_blocks::pairs_of_block(9), pair_blocks::pairs_of_block(3));
    // Rooms of 4096, all used, fill each block to the last pair.
    pair_blocks blocks;
    std::uint32_t next = 0;
    std::size_t total = 0;
    for (std::size_t b = 0; b < 6; ++b) {
        total += pair_blocks::pairs_of_block(b);
    }
    while (blocks.size() < total) {
        obbsat::pair_index* out = blocks.room(4096);
        for (std::size_t i = 0; i < 4096; ++i) {
            out[i] = {next++, 3};
        }
        blocks.add(4096);
    }
    const auto spans = blocks.spans();
    ASSERT_EQ(spans.size(), 6u);
    std::uint32_t expected = 0;
    for (std::size_t b = 0; b < spans.size(); ++b) {
        EXPECT_EQ(spans[b].size, pair_blocks::pairs_of_block(b)) << "block " << b;
        EXPECT_EQ(spans[b].data[0].a, expected) << "block " << b;
        expected += static_cast<std::uint32_t>(spans[b].size);
    }
}
