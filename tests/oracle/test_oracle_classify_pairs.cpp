// The batch entry point: the same answers as one classify per pair for any
// thread count, and checked input with nothing written on an error.
#include <obbsat/oracle/classify_pairs.hpp>

#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using obbsat::pair_index;
using obbsat::rect;
using obbsat::oracle::contact;

// A value no classification produces, to see that nothing was written.
const contact not_written = static_cast<contact>(0xab);

std::vector<rect> lattice_rects(std::size_t count, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<rect> rects(count);
    for (rect& r : rects) {
        float v[8];
        for (float& x : v) {
            x = static_cast<float>(static_cast<int>(random.below(9)) - 4);
        }
        r = rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
    }
    return rects;
}

TEST(classify_pairs, matches_one_classify_per_pair_for_every_thread_count) {
    const std::vector<rect> rects = lattice_rects(3000, 3);
    obbsat::seeded_random random(4);
    std::vector<pair_index> pairs(50000);
    for (pair_index& p : pairs) {
        p = pair_index{static_cast<std::uint32_t>(random.below(rects.size())),
                       static_cast<std::uint32_t>(random.below(rects.size()))};
    }
    std::vector<contact> expected(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        expected[i] = obbsat::oracle::classify(rects[pairs[i].a], rects[pairs[i].b]);
    }
    for (const unsigned threads : {1u, 2u, 3u, 0u}) {
        EXPECT_EQ(obbsat::oracle::classify_pairs(rects, pairs, threads), expected) << threads;
    }
}

TEST(classify_pairs, empty_batch) {
    EXPECT_TRUE(obbsat::oracle::classify_pairs(std::vector<rect>{}, {}, 2).empty());
}

TEST(classify_pairs, an_index_out_of_range_names_the_pair_and_writes_nothing) {
    const std::vector<rect> rects = lattice_rects(10, 1);
    std::vector<pair_index> pairs(20000, pair_index{1, 2});
    pairs[12345] = pair_index{3, 10};
    std::vector<contact> out(pairs.size(), not_written);
    try {
        obbsat::oracle::classify_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(),
                                       out.data(), 2);
        FAIL() << "expected std::out_of_range";
    } catch (const std::out_of_range& error) {
        EXPECT_NE(std::string(error.what()).find("pair 12345"), std::string::npos) << error.what();
    }
    for (const contact c : out) {
        ASSERT_EQ(c, not_written);
    }
}

TEST(classify_pairs, a_non_finite_rect_is_named_and_nothing_is_written) {
    std::vector<rect> rects = lattice_rects(10, 2);
    rects[7].lr.y = INFINITY;
    const std::vector<pair_index> pairs(100, pair_index{0, 1});
    std::vector<contact> out(pairs.size(), not_written);
    try {
        obbsat::oracle::classify_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(),
                                       out.data(), 1);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("rect 7"), std::string::npos) << error.what();
    }
    for (const contact c : out) {
        ASSERT_EQ(c, not_written);
    }
}

}  // namespace
