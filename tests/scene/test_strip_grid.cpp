// The layout of a scene query's sweep (scene/strip_grid.hpp): q_of and
// strip_of are monotone (x <= y gives q(x) <= q(y)) over every float there is,
// negative zero, subnormals, the largest finite floats and the infinities
// included, and stay in [0, q_max] and [0, strips - 1], NaN included; they
// are the floors and clamps the header states, at strip boundaries too;
// key_of is (strip << q_bits) | q and sorts by strip, then by x; grid_for
// leaves a sixteenth of the extent on every side, cuts strips of at most
// strip_factor mean heights, at most one per rectangle and at most 2^20, and
// grid_still_fits accepts an extent inside the grid's range whose mean height
// is within a factor 1.5 of the one the strips were cut for.
#include "scene/strip_grid.hpp"

#include <gtest/gtest.h>

#include <obbsat/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::detail::bounds_extent;
using obbsat::detail::grid_for;
using obbsat::detail::grid_still_fits;
using obbsat::detail::strip_grid;

constexpr float inf = std::numeric_limits<float>::infinity();
constexpr float nan_value = std::numeric_limits<float>::quiet_NaN();
constexpr float largest = std::numeric_limits<float>::max();
constexpr float smallest_normal = std::numeric_limits<float>::min();
constexpr float smallest_subnormal = std::numeric_limits<float>::denorm_min();

float below(float x) { return std::nextafter(x, -inf); }
float above(float x) { return std::nextafter(x, inf); }

/// Values where a quantization could go wrong, and the neighbours of the
/// grid's own edges.
std::vector<float> hard_values(const strip_grid& grid) {
    std::vector<float> v = {-inf, -largest, below(-largest / 2), -1e30f, -16777217.0f, -16777216.0f, -3.5f, -1.0f,
                            -smallest_normal, below(-smallest_subnormal), -smallest_subnormal, -0.0f, 0.0f,
                            smallest_subnormal, 3 * smallest_subnormal, below(smallest_normal), smallest_normal,
                            0.5f, 1.0f, above(1.0f), 16777216.0f, 16777218.0f, 1e30f, largest, inf};
    for (const double edge : {grid.x_low, grid.x_high, grid.y_low, grid.y_high}) {
        const float f = static_cast<float>(edge);
        if (std::isfinite(f)) {
            v.insert(v.end(), {below(below(f)), below(f), f, above(f), above(above(f))});
        }
    }
    return v;
}

/// Floats of every exponent and both signs, from their bits.
std::vector<float> any_floats(std::uint32_t seed, std::size_t count) {
    obbsat::seeded_random random(seed);
    std::vector<float> out;
    while (out.size() < count) {
        const auto bits = static_cast<std::uint32_t>(random.next());
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isnan(f)) {
            out.push_back(f);
        }
    }
    return out;
}

/// Grids over extents near zero, subnormal, huge, far from the origin, flat,
/// and the default one.
std::vector<std::pair<std::string, strip_grid>> grids() {
    return {
        {"default", strip_grid{}},
        {"scene", grid_for({0, 100, 0, 100, 5}, 1000, 2)},
        {"around zero", grid_for({-3, 3, -3, 3, 0.25}, 50, 2)},
        {"subnormal", grid_for({-1e-40, 1e-40, -1e-40, 1e-40, 1e-41}, 100, 2)},
        {"every float", grid_for({-largest, largest, -largest, largest, 1e30}, 1u << 22, 2)},
        {"far from the origin", grid_for({1e30, 1.0001e30, -1e30, -0.9999e30, 1e25}, 100000, 2)},
        {"many strips", grid_for({0, 1, 0, 1, 1e-9}, 1u << 22, 2)},
        {"flat", grid_for({5, 5, 7, 7, 0}, 10, 2)},
    };
}

TEST(strip_grid, q_of_and_strip_of_are_monotone_over_hard_values) {
    for (const auto& [name, grid] : grids()) {
        const std::vector<float> v = hard_values(grid);
        for (const float x : v) {
            for (const float y : v) {
                if (x <= y) {
                    ASSERT_LE(grid.q_of(x), grid.q_of(y)) << name << std::hexfloat << ": x " << x << ", y " << y;
                    ASSERT_LE(grid.strip_of(x), grid.strip_of(y)) << name << std::hexfloat << ": x " << x << ", y " << y;
                }
            }
        }
        // Both zeros are one position.
        EXPECT_EQ(grid.q_of(-0.0f), grid.q_of(0.0f)) << name;
        EXPECT_EQ(grid.strip_of(-0.0f), grid.strip_of(0.0f)) << name;
    }
}

TEST(strip_grid, q_of_and_strip_of_are_monotone_over_random_floats_of_every_exponent) {
    std::vector<float> v = any_floats(20261126, 200'000);
    std::sort(v.begin(), v.end());
    for (const auto& [name, grid] : grids()) {
        for (std::size_t i = 1; i < v.size(); ++i) {
            ASSERT_LE(grid.q_of(v[i - 1]), grid.q_of(v[i])) << name << std::hexfloat << ": " << v[i - 1] << ", " << v[i];
            ASSERT_LE(grid.strip_of(v[i - 1]), grid.strip_of(v[i])) << name << std::hexfloat << ": " << v[i - 1] << ", " << v[i];
        }
    }
}

TEST(strip_grid, q_of_and_strip_of_stay_in_range_nan_and_infinities_included) {
    for (const auto& [name, grid] : grids()) {
        std::vector<float> v = hard_values(grid);
        v.push_back(nan_value);
        v.push_back(-nan_value);
        for (const float x : v) {
            EXPECT_LE(grid.q_of(x), grid.q_max) << name << ": " << x;
            EXPECT_LT(grid.strip_of(x), grid.strips) << name << ": " << x;
        }
        EXPECT_EQ(grid.q_of(-inf), 0u) << name;
        EXPECT_EQ(grid.strip_of(-inf), 0u) << name;
        if (grid.x_scale > 0) {
            EXPECT_EQ(grid.q_of(inf), grid.q_max) << name;
        }
        EXPECT_EQ(grid.strip_of(inf), grid.strips - 1) << name;
    }
}

TEST(strip_grid, q_of_is_the_clamped_floor_of_the_scaled_offset) {
    strip_grid grid;
    grid.x_low = -2;
    grid.x_scale = 4;  // quarters
    grid.q_bits = 8;
    grid.q_max = 255;
    EXPECT_EQ(grid.q_of(-2.0f), 0u);
    EXPECT_EQ(grid.q_of(-1.75f), 1u);
    EXPECT_EQ(grid.q_of(below(-1.75f)), 0u);
    EXPECT_EQ(grid.q_of(0.0f), 8u);
    EXPECT_EQ(grid.q_of(-0.0f), 8u);
    EXPECT_EQ(grid.q_of(0.3f), 9u);
    EXPECT_EQ(grid.q_of(61.5f), 254u);
    EXPECT_EQ(grid.q_of(61.75f), 255u);
    EXPECT_EQ(grid.q_of(below(61.75f)), 254u);
    EXPECT_EQ(grid.q_of(62.0f), 255u);
    EXPECT_EQ(grid.q_of(1e30f), 255u);
    EXPECT_EQ(grid.q_of(-3.0f), 0u);
    EXPECT_EQ(grid.q_of(-64.0f), 0u);
    // No scale: everything is position 0.
    grid.x_scale = 0;
    for (const float x : {-inf, -1.0f, 0.0f, 1e30f, inf}) {
        EXPECT_EQ(grid.q_of(x), 0u) << x;
    }
}

TEST(strip_grid, strip_of_cuts_at_every_strip_boundary) {
    strip_grid grid;
    grid.y_low = 10;
    grid.y_high = 20;
    grid.y_scale = 0.5;  // strips two units tall
    grid.strips = 5;
    grid.strip_bits = 3;
    for (std::uint32_t k = 0; k < grid.strips; ++k) {
        const float boundary = 10.0f + 2.0f * static_cast<float>(k);
        EXPECT_EQ(grid.strip_of(boundary), k) << boundary;
        if (k > 0) {
            EXPECT_EQ(grid.strip_of(below(boundary)), k - 1) << boundary;
        }
        EXPECT_EQ(grid.strip_of(boundary + 1.0f), k) << boundary;
    }
    EXPECT_EQ(grid.strip_of(20.0f), 4u);  // the top belongs to the last strip
    EXPECT_EQ(grid.strip_of(above(20.0f)), 4u);
    EXPECT_EQ(grid.strip_of(9.0f), 0u);
    EXPECT_EQ(grid.strip_of(-1e30f), 0u);
    EXPECT_EQ(grid.strip_of(1e30f), 4u);
    // One strip: everything is strip 0.
    grid.strips = 1;
    for (const float y : {-inf, 9.0f, 15.0f, 21.0f, inf}) {
        EXPECT_EQ(grid.strip_of(y), 0u) << y;
    }
}

TEST(strip_grid, key_of_is_the_strip_above_the_position_and_sorts_by_strip_then_x) {
    for (const auto& [name, grid] : grids()) {
        EXPECT_EQ(grid.key_bits(), grid.strip_bits + grid.q_bits) << name;
        ASSERT_LE(grid.key_bits(), 32u) << name;
        const std::uint64_t key_limit = std::uint64_t{1} << grid.key_bits();
        const std::vector<float> v = hard_values(grid);
        for (const float x : v) {
            for (const float y : v) {
                const std::uint32_t key = grid.key_of(x, y);
                ASSERT_EQ(key, (grid.strip_of(y) << grid.q_bits) | grid.q_of(x)) << name;
                ASSERT_LT(key, key_limit) << name << ": " << x << ", " << y;
                ASSERT_EQ(key >> grid.q_bits, grid.strip_of(y)) << name;
                ASSERT_EQ(key & grid.q_max, grid.q_of(x)) << name;
            }
        }
    }
}

TEST(strip_grid, grid_for_leaves_a_sixteenth_on_every_side_and_cuts_strips_of_the_asked_height) {
    // Extent 256 by 256: the grid spans [-16, 272] both ways; strips of at
    // most 2 * 18 = 36 over 288 are 9 strips of 32.
    const bounds_extent extent{0, 256, 0, 256, 18};
    const strip_grid grid = grid_for(extent, 1000, 2);
    EXPECT_EQ(grid.x_low, -16.0);
    EXPECT_EQ(grid.x_high, 272.0);
    EXPECT_EQ(grid.y_low, -16.0);
    EXPECT_EQ(grid.y_high, 272.0);
    EXPECT_EQ(grid.height_basis, 18.0);
    EXPECT_EQ(grid.strips, 9u);
    EXPECT_EQ(grid.y_scale, 1.0 / 32);
    EXPECT_EQ(grid.strip_bits, 4u);
    EXPECT_EQ(grid.q_bits, 16u);
    EXPECT_EQ(grid.q_max, 65535u);
    EXPECT_EQ(grid.x_scale, 65535.0 / 288);
    EXPECT_EQ(grid.q_of(-16.0f), 0u);
    EXPECT_EQ(grid.q_of(272.0f), 65535u);
    EXPECT_EQ(grid.q_of(128.0f), 65535u / 2);  // (128 + 16) / 288 of the way
    for (std::uint32_t k = 0; k < 9; ++k) {
        const float boundary = -16.0f + 32.0f * static_cast<float>(k);
        EXPECT_EQ(grid.strip_of(boundary), k) << boundary;
        if (k > 0) {
            EXPECT_EQ(grid.strip_of(below(boundary)), k - 1) << boundary;
        }
    }
    EXPECT_EQ(grid.strip_of(272.0f), 8u);
    EXPECT_EQ(grid.key_of(-16.0f, 16.0f), 1u << 16);
    EXPECT_EQ(grid.key_of(272.0f, 272.0f), (8u << 16) | 65535u);
}

TEST(strip_grid, grid_for_strips_are_at_most_strip_factor_mean_heights_tall) {
    for (const double factor : {0.5, 1.0, 2.0, 3.0}) {
        for (const double mean : {0.3, 1.0, 7.0, 40.0}) {
            const bounds_extent extent{-50, 150, -100, 300, mean};
            const strip_grid grid = grid_for(extent, 100000, factor);
            const double strip_height = (grid.y_high - grid.y_low) / grid.strips;
            EXPECT_LE(strip_height, factor * mean) << factor << " x " << mean;
            EXPECT_GT(strip_height * 2, factor * mean) << factor << " x " << mean << ": needlessly thin";
            EXPECT_LT(grid.strips - 1, 1u << grid.strip_bits);
            EXPECT_GE(grid.strips - 1, grid.strip_bits == 0 ? 0u : 1u << (grid.strip_bits - 1));
        }
    }
}

TEST(strip_grid, grid_for_cuts_at_most_one_strip_per_rectangle_and_at_most_two_to_the_twenty) {
    const bounds_extent extent{0, 256, 0, 256, 18};
    EXPECT_EQ(grid_for(extent, 3, 2).strips, 3u);
    EXPECT_EQ(grid_for(extent, 3, 2).strip_bits, 2u);
    EXPECT_EQ(grid_for(extent, 1, 2).strips, 1u);
    EXPECT_EQ(grid_for(extent, 0, 2).strips, 1u);
    EXPECT_EQ(grid_for(extent, 0, 2).strip_bits, 0u);
    EXPECT_EQ(grid_for(extent, 0, 2).q_bits, 16u);

    const strip_grid many = grid_for({0, 256, 0, 256, 1e-6}, 1u << 22, 2);
    EXPECT_EQ(many.strips, 1u << 20);
    EXPECT_EQ(many.strip_bits, 20u);
    EXPECT_EQ(many.q_bits, 8u);  // x resolution gives way, to at least eight bits
    EXPECT_EQ(many.q_max, 255u);
    EXPECT_EQ(many.key_bits(), 28u);
    EXPECT_EQ(many.strip_of(272.0f), (1u << 20) - 1);

    // Without a usable mean height, strips as fine as the count allows.
    for (const double mean : {0.0, -1.0, std::nan("")}) {
        const strip_grid g = grid_for({0, 256, 0, 256, mean}, 1000, 2);
        EXPECT_EQ(g.strips, 1000u) << mean;
        EXPECT_EQ(g.strip_bits, 10u) << mean;
        EXPECT_EQ(g.q_bits, 14u) << mean;
    }
}

TEST(strip_grid, grid_for_a_flat_extent_is_one_strip_and_one_position) {
    const strip_grid grid = grid_for({5, 5, 7, 7, 0}, 10, 2);
    EXPECT_EQ(grid.strips, 1u);
    EXPECT_EQ(grid.x_scale, 0.0);
    for (const float v : {-inf, 5.0f, 7.0f, 1e30f, inf}) {
        EXPECT_EQ(grid.q_of(v), 0u) << v;
        EXPECT_EQ(grid.strip_of(v), 0u) << v;
    }
}

TEST(strip_grid, grid_still_fits_inside_its_margins_and_within_half_again_the_mean_height) {
    const bounds_extent extent{0, 256, 0, 256, 18};
    const strip_grid grid = grid_for(extent, 1000, 2);
    EXPECT_TRUE(grid_still_fits(grid, extent));
    EXPECT_TRUE(grid_still_fits(grid, {-16, 272, -16, 272, 18}));  // the margins, exactly
    EXPECT_FALSE(grid_still_fits(grid, {-16.001, 256, 0, 256, 18}));
    EXPECT_FALSE(grid_still_fits(grid, {0, 272.001, 0, 256, 18}));
    EXPECT_FALSE(grid_still_fits(grid, {0, 256, -16.001, 256, 18}));
    EXPECT_FALSE(grid_still_fits(grid, {0, 256, 0, 272.001, 18}));
    EXPECT_TRUE(grid_still_fits(grid, {0, 256, 0, 256, 27}));  // 1.5 times
    EXPECT_FALSE(grid_still_fits(grid, {0, 256, 0, 256, 27.001}));
    EXPECT_TRUE(grid_still_fits(grid, {0, 256, 0, 256, 12}));  // a 1.5th
    EXPECT_FALSE(grid_still_fits(grid, {0, 256, 0, 256, 11.999}));
    EXPECT_FALSE(grid_still_fits(grid, {0, 256, 0, 256, std::nan("")}));
}

}  // namespace
