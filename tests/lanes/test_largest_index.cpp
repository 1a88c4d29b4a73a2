// Every backend's largest index of a pair list (the pass that checks a list
// against its store) must be the plain maximum over both indices of every
// pair: at every position of a list, in whole and partial vectors, with
// indices past 2^31 (where a signed comparison would order them wrongly).
#include "backends/backend_cases.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace {

std::uint32_t plain_largest(const std::vector<obbsat::pair_index>& pairs) {
    std::uint32_t largest = 0;
    for (const obbsat::pair_index& p : pairs) {
        largest = std::max({largest, p.a, p.b});
    }
    return largest;
}

class largest_index_lanes : public ::testing::TestWithParam<obbsat_test::backend_case> {};

TEST_P(largest_index_lanes, is_the_largest_of_both_indices_of_every_pair) {
    if (!obbsat::cpu_supports(GetParam().id)) {
        GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(GetParam().id);
    }
    const auto largest = GetParam().table->largest_index;
    obbsat::seeded_random random(20261124);
    EXPECT_EQ(largest(nullptr, 0), 0u);
    // Every length up to several vectors of the widest backend; the largest
    // index put in turn at every pair, on either side.
    for (std::size_t n = 1; n <= 70; ++n) {
        for (const std::uint32_t ceiling : {1000u, 0x7fffffffu, 0xffffffffu}) {
            std::vector<obbsat::pair_index> pairs(n);
            for (obbsat::pair_index& p : pairs) {
                p = {static_cast<std::uint32_t>(random.below(1000)), static_cast<std::uint32_t>(random.below(1000))};
            }
            for (std::size_t at = 0; at < n; ++at) {
                for (const bool second : {false, true}) {
                    std::vector<obbsat::pair_index> with = pairs;
                    (second ? with[at].b : with[at].a) = ceiling;
                    EXPECT_EQ(largest(with.data(), n), plain_largest(with))
                        << "length " << n << ", " << ceiling << " as index " << (second ? "b" : "a") << " of pair "
                        << at;
                }
            }
        }
    }
    // Long random lists with indices over the whole 32-bit range.
    for (std::size_t n : {4096u, 100'003u}) {
        std::vector<obbsat::pair_index> pairs(n);
        for (obbsat::pair_index& p : pairs) {
            p = {static_cast<std::uint32_t>(random.next()), static_cast<std::uint32_t>(random.next() >> 1)};
        }
        EXPECT_EQ(largest(pairs.data(), n), plain_largest(pairs)) << "length " << n;
    }
}

INSTANTIATE_TEST_SUITE_P(backends, largest_index_lanes, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
