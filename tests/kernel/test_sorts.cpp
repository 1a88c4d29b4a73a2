// The scene queries' sorts against std::stable_sort: radix_sort on one
// thread and split over two (the same result either way, equal keys in their
// input order), bucket_sort, and repair_sort on nearly sorted input and past
// its move budget.
#include "radix_sort.hpp"

#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace {

using keyed = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// Keys below 2^key_bits, many repeated; values the input positions.
void random_input(std::size_t n, unsigned key_bits, std::uint64_t seed, std::vector<std::uint32_t>& keys,
                  std::vector<std::uint32_t>& values) {
    obbsat::seeded_random random(seed);
    keys.resize(n);
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = static_cast<std::uint32_t>(random.next()) & ((std::uint32_t{1} << key_bits) - 1);
        values[i] = static_cast<std::uint32_t>(i);
    }
}

/// What a stable sort by key >> shift gives.
keyed stably_sorted(const std::vector<std::uint32_t>& keys, const std::vector<std::uint32_t>& values,
                    unsigned shift) {
    keyed out(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        out[i] = {keys[i], values[i]};
    }
    std::stable_sort(out.begin(), out.end(), [shift](const auto& x, const auto& y) {
        return (x.first >> shift) < (y.first >> shift);
    });
    return out;
}

keyed zipped(const std::vector<std::uint32_t>& keys, const std::vector<std::uint32_t>& values) {
    keyed out(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        out[i] = {keys[i], values[i]};
    }
    return out;
}

TEST(radix_sort, equals_a_stable_sort_on_one_thread_and_two) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{300000}}) {
        for (const unsigned key_bits : {4u, 20u, 32u}) {
            for (const std::size_t parts : {std::size_t{1}, std::size_t{2}}) {
                std::vector<std::uint32_t> keys, values;
                random_input(n, key_bits == 32 ? 31 : key_bits, n + key_bits, keys, values);
                const keyed want = stably_sorted(keys, values, 0);
                obbsat::detail::radix_buffer packed, spare;
                obbsat::detail::radix_sort(keys.data(), values.data(), n, key_bits, packed, spare, parts);
                EXPECT_EQ(zipped(keys, values), want) << n << " keys of " << key_bits << " bits, " << parts << " parts";
            }
        }
    }
}

TEST(bucket_sort, equals_a_stable_sort_by_bucket) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{5000}, std::size_t{400000}}) {
        const unsigned shift = 12;
        const std::size_t buckets = 300;
        std::vector<std::uint32_t> keys, values;
        random_input(n, 20, n + 7, keys, values);
        for (std::uint32_t& k : keys) {
            k = (k % (static_cast<std::uint32_t>(buckets) << shift));  // every key >> shift below buckets
        }
        const keyed want = stably_sorted(keys, values, shift);
        std::vector<std::uint32_t> spare_keys, spare_values;
        obbsat::detail::bucket_sort(keys.data(), values.data(), n, shift, buckets, spare_keys, spare_values);
        EXPECT_EQ(zipped(keys, values), want) << n << " keys";
    }
}

TEST(repair_sort, sorts_nearly_sorted_input_and_gives_up_past_its_budget) {
    obbsat::seeded_random random(3);
    std::vector<std::uint32_t> keys(20000), values(20000);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        keys[i] = static_cast<std::uint32_t>(4 * i + random.below(12));  // each key a few places off
        values[i] = static_cast<std::uint32_t>(i);
    }
    const keyed want = stably_sorted(keys, values, 0);
    std::size_t moved = 0;
    ASSERT_TRUE(obbsat::detail::repair_sort(keys.data(), values.data(), keys.size(), keys.size(), &moved));
    EXPECT_EQ(zipped(keys, values), want);
    EXPECT_GT(moved, 0u);
    // Reversed input needs n^2 / 2 moves: refused within a budget of n, still a permutation.
    std::vector<std::uint32_t> reversed(5000), ids(5000);
    for (std::size_t i = 0; i < reversed.size(); ++i) {
        reversed[i] = static_cast<std::uint32_t>(reversed.size() - i);
        ids[i] = static_cast<std::uint32_t>(i);
    }
    EXPECT_FALSE(obbsat::detail::repair_sort(reversed.data(), ids.data(), ids.size(), ids.size()));
    std::sort(ids.begin(), ids.end());
    std::vector<std::uint32_t> all(ids.size());
    std::iota(all.begin(), all.end(), 0u);
    EXPECT_EQ(ids, all);
}

}  // namespace
