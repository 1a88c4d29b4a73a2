// Every backend's fused multiply-add must round x * y + z once, bit for bit
// as std::fma does: method conservative's projections and margins depend on
// it. The cases that catch a sum rounded twice (first to double, then to
// float) are built on purpose: their exact value sits a hair off a float
// midpoint, where the double rounding lands on the midpoint itself.
#include "backends/backend_cases.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct triples {
    std::vector<float> x, y, z;

    void add(float a, float b, float c) {
        x.push_back(a);
        y.push_back(b);
        z.push_back(c);
    }
};

std::uint32_t bits_of(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

float from_bits(std::uint32_t b) {
    float v;
    std::memcpy(&v, &b, sizeof v);
    return v;
}

/// x * y = 1 - 2^-46 or 1 + 2^-46 (times powers of two), z a float whose
/// spacing makes x * y + z fall just below or above a float midpoint.
triples near_midpoints(obbsat::seeded_random& random, std::size_t count) {
    triples t;
    const float below[2] = {1.0f + 0x1p-23f, 1.0f - 0x1p-23f};  // product 1 - 2^-46
    const float above[2] = {1.0f + 0x1p-23f, 1.0f + 0x1p-23f};  // product 1 + 2^-22 + 2^-46
    for (std::size_t i = 0; i < count; ++i) {
        const float* pair = (i % 2 == 0) ? below : above;
        const int shift = static_cast<int>(random.below(160)) - 80;
        const float scale = std::ldexp(1.0f, shift);
        // z in [2^24, 2^25) has spacing 2, so its neighbours' midpoint is z + 1.
        const float z = std::ldexp(1.0f + static_cast<float>(random.below(1u << 23)) * 0x1p-23f, 24);
        const float sign_xy = (random.next() & 1u) ? -1.0f : 1.0f;
        const float sign_z = (random.next() & 1u) ? -1.0f : 1.0f;
        t.add(pair[0] * scale * sign_xy, pair[1], sign_z * z * scale);
    }
    return t;
}

/// Finite floats from random bit patterns, exponents spread over the range.
triples random_bits(obbsat::seeded_random& random, std::size_t count) {
    triples t;
    auto finite = [&random] {
        for (;;) {
            const float v = from_bits(static_cast<std::uint32_t>(random.next()));
            if (std::isfinite(v)) {
                return v;
            }
        }
    };
    for (std::size_t i = 0; i < count; ++i) {
        t.add(finite(), finite(), finite());
    }
    return t;
}

/// Operands of similar magnitude, as projections see them: cancellation,
/// subnormal and overflowing results included.
triples similar_magnitudes(obbsat::seeded_random& random, std::size_t count) {
    triples t;
    for (std::size_t i = 0; i < count; ++i) {
        const int e = static_cast<int>(random.below(250)) - 125;
        const float a = std::ldexp(random.uniform(-1.0f, 1.0f), e / 2);
        const float b = std::ldexp(random.uniform(-1.0f, 1.0f), e - e / 2);
        const float c = -(a * b) * random.uniform(0.999f, 1.001f);
        t.add(a, b, c);
    }
    return t;
}

void expect_same_as_std_fma(const obbsat::detail::kernel_table& table, const triples& t, const std::string& what) {
    std::vector<float> out(t.x.size(), -1.0f);
    table.fused_multiply_add(t.x.data(), t.y.data(), t.z.data(), t.x.size(), out.data());
    std::size_t shown = 0;
    for (std::size_t i = 0; i < t.x.size(); ++i) {
        const float want = std::fma(t.x[i], t.y[i], t.z[i]);
        const bool same = std::isnan(want) ? std::isnan(out[i]) : bits_of(want) == bits_of(out[i]);
        if (!same && shown++ < 5) {
            ADD_FAILURE() << what << " case " << i << ": fma(" << std::hexfloat << t.x[i] << ", " << t.y[i] << ", "
                          << t.z[i] << ") = " << want << ", lanes give " << out[i];
        }
    }
    EXPECT_EQ(shown, 0u) << what;
}

class fused_multiply_add : public ::testing::TestWithParam<obbsat_test::backend_case> {};

TEST_P(fused_multiply_add, rounds_once_like_std_fma) {
    if (!obbsat::cpu_supports(GetParam().id)) {
        GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(GetParam().id);
    }
    const auto& table = *GetParam().table;
    obbsat::seeded_random random(20261121);
    expect_same_as_std_fma(table, near_midpoints(random, 200'000), "near a float midpoint");
    expect_same_as_std_fma(table, random_bits(random, 1'000'000), "random bit patterns");
    expect_same_as_std_fma(table, similar_magnitudes(random, 1'000'000), "similar magnitudes");

    // Every length up to a few vectors, so partial vectors are covered.
    for (std::size_t n = 0; n <= 50; ++n) {
        expect_same_as_std_fma(table, near_midpoints(random, n), "length " + std::to_string(n));
    }
}

TEST(fused_multiply_add_cases, the_midpoint_case_separates_one_rounding_from_two) {
    // 2^24 + 2 + (1 - 2^-46): rounded once, 2^24 + 2; rounded to double
    // first, the midpoint 2^24 + 3, which then rounds to even, 2^24 + 4.
    const float x = 1.0f + 0x1p-23f, y = 1.0f - 0x1p-23f, z = 0x1p24f + 2.0f;
    EXPECT_EQ(std::fma(x, y, z), 0x1p24f + 2.0f);
    const double twice = static_cast<double>(x) * static_cast<double>(y) + static_cast<double>(z);
    EXPECT_EQ(static_cast<float>(twice), 0x1p24f + 4.0f) << "the case must tell the two apart";
}


INSTANTIATE_TEST_SUITE_P(backends, fused_multiply_add, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
