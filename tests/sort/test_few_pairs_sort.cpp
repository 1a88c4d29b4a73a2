// sort_few_pairs against std::sort of the same pairs: keys that need one to
// six passes, an empty and a one-pair list, equal pairs
// with different tags, and scratch reused from a larger sort.
#include "sort/few_pairs_sort.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using obbsat::detail::few_pairs_sort_scratch;
using obbsat::detail::sort_few_pairs;
using obbsat::detail::tagged_pair;

bool by_pair_then_tag(const tagged_pair& x, const tagged_pair& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.tag < y.tag;
}

/// Sorts `pairs` both ways and compares: the same pairs in (a, b) order, and
/// the same set of tags under each (a, b) (equal pairs keep no particular order).
void expect_sorted_like_std(std::vector<tagged_pair> pairs, few_pairs_sort_scratch& scratch) {
    std::vector<tagged_pair> want = pairs;
    std::sort(want.begin(), want.end(), by_pair_then_tag);
    sort_few_pairs(pairs, scratch);
    ASSERT_EQ(pairs.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        ASSERT_TRUE(pairs[i].a == want[i].a && pairs[i].b == want[i].b) << "pair " << i;
    }
    // Within each run of equal (a, b), the tags are the same set.
    std::size_t run = 0;
    for (std::size_t i = 1; i <= pairs.size(); ++i) {
        if (i == pairs.size() || pairs[i].a != pairs[run].a || pairs[i].b != pairs[run].b) {
            std::vector<tagged_pair> got(pairs.begin() + static_cast<std::ptrdiff_t>(run),
                                         pairs.begin() + static_cast<std::ptrdiff_t>(i));
            std::sort(got.begin(), got.end(), by_pair_then_tag);
            for (std::size_t k = run; k < i; ++k) {
                ASSERT_EQ(got[k - run].tag, want[k].tag) << "pair " << k;
            }
            run = i;
        }
    }
}

std::vector<tagged_pair> random_pairs(std::size_t count, std::uint32_t a_below, std::uint32_t b_below,
                                      unsigned seed) {
    std::mt19937 random(seed);
    std::vector<tagged_pair> pairs;
    for (std::size_t i = 0; i < count; ++i) {
        const auto a = static_cast<std::uint32_t>(random() % a_below);
        const auto b = static_cast<std::uint32_t>(random() % b_below);
        pairs.push_back(tagged_pair{a, b, static_cast<std::uint32_t>(i)});
    }
    return pairs;
}

}  // namespace

TEST(few_pairs_sort, sorts_like_std_sort_for_every_count_of_passes) {
    few_pairs_sort_scratch scratch;
    // Keys of 6, 21, 24 (two whole digits), 34, 37, 49 and 64 bits: one,
    // two, two, three, four, five and six passes of 12 bits, every pass's
    // counts taken in one read.
    expect_sorted_like_std(random_pairs(1000, 8, 8, 1), scratch);
    expect_sorted_like_std(random_pairs(5000, 2048, 1024, 2), scratch);
    expect_sorted_like_std(random_pairs(4000, 4096, 4096, 8), scratch);
    expect_sorted_like_std(random_pairs(7000, 100000, 100000, 3), scratch);
    expect_sorted_like_std(random_pairs(6000, 1u << 19, 1u << 18, 9), scratch);
    expect_sorted_like_std(random_pairs(6000, 1u << 25, 1u << 24, 10), scratch);
    expect_sorted_like_std(random_pairs(3000, 0xffffffffu, 0xffffffffu, 4), scratch);
    // One pass of 12 bits and one of a single bit: a key of 13 bits.
    expect_sorted_like_std(random_pairs(2000, 128, 64, 5), scratch);
}

TEST(few_pairs_sort, keeps_equal_pairs_and_handles_tiny_lists) {
    few_pairs_sort_scratch scratch;
    expect_sorted_like_std({}, scratch);
    expect_sorted_like_std({tagged_pair{5, 9, 0}}, scratch);
    expect_sorted_like_std({tagged_pair{5, 9, 0}, tagged_pair{5, 2, 1}}, scratch);
    // Many equal pairs with different tags, and zeros.
    std::vector<tagged_pair> pairs;
    for (std::uint32_t i = 0; i < 500; ++i) {
        pairs.push_back(tagged_pair{i % 3, i % 2 == 0 ? 0u : 7u, i});
    }
    expect_sorted_like_std(pairs, scratch);
    // Scratch left larger by an earlier sort serves a smaller one.
    expect_sorted_like_std(random_pairs(20000, 50000, 50000, 6), scratch);
    expect_sorted_like_std(random_pairs(50, 50000, 50000, 7), scratch);
}
