// Every backend's bounds kernel must give, bit for bit, the bounds of
// obbsat::ref::bounds_of (obbsat/ref/bounds.hpp): the scene queries compare
// them to pick candidates, and the answer must not depend on the backend.
// Poses across every scale (subnormal half extents, rotations far from unit
// length, coordinates whose bounds overflow to infinity) and corners with
// zeros of both signs, at every length up to a few vectors.
#include "backends/backend_cases.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using obbsat::store_kind;

std::uint32_t bits_of(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

/// A float of random sign and mantissa with its exponent drawn from [low, high].
float spread(obbsat::seeded_random& random, int low, int high) {
    const int e = low + static_cast<int>(random.below(static_cast<std::uint32_t>(high - low + 1)));
    const float v = std::ldexp(random.uniform(0.5f, 1.0f), e);
    return (random.next() & 1u) ? -v : v;
}

/// Pose records (cx, cy, hx, hy, c, s, 0, 0) over every scale.
std::vector<float> pose_records(obbsat::seeded_random& random, std::size_t count) {
    std::vector<float> out;
    for (std::size_t i = 0; i < count; ++i) {
        const int kind = static_cast<int>(random.below(4));
        float v[8] = {};
        if (kind == 0) {  // a scene: unit rotations, moderate sizes
            const float angle = random.uniform(0.0f, 6.2831853f);
            const float r[8] = {random.uniform(-1e4f, 1e4f), random.uniform(-1e4f, 1e4f), random.uniform(0.0f, 50.0f),
                                random.uniform(0.0f, 50.0f), std::cos(angle), std::sin(angle), 0, 0};
            std::memcpy(v, r, sizeof v);
        } else {  // anything finite: tiny, huge, subnormal, overflowing
            v[0] = spread(random, -149, 127);
            v[1] = spread(random, -149, 127);
            v[2] = std::fabs(spread(random, -149, 127));
            v[3] = std::fabs(spread(random, -149, 127));
            v[4] = spread(random, -149, 127);
            v[5] = spread(random, -149, 127);
            if (kind == 2) {
                v[2] = 0.0f;  // a segment
            }
            if (kind == 3) {
                v[4] = 0.0f;  // an axis-aligned rotation of any length
            }
        }
        out.insert(out.end(), v, v + 8);
    }
    return out;
}

/// Corner records, coordinates from a few values so that ties and zeros of
/// both signs are common, or spread over the range.
std::vector<float> corner_records(obbsat::seeded_random& random, std::size_t count) {
    const float few[] = {0.0f, -0.0f, 1.0f, -1.0f, 0x1p-149f, -0x1p-149f, 3.5f};
    std::vector<float> out;
    for (std::size_t i = 0; i < count * 8; ++i) {
        out.push_back(random.below(2) == 0 ? few[random.below(7)] : spread(random, -149, 127));
    }
    return out;
}

void expect_reference_bounds(const obbsat::detail::kernel_table& table, store_kind kind,
                             const std::vector<float>& records, const std::string& what) {
    const std::size_t n = records.size() / 8;
    std::vector<float> lo_x(n + 1, -7.0f), lo_y(n + 1, -7.0f), hi_x(n + 1, -7.0f), hi_y(n + 1, -7.0f);
    table.bounds(kind, records.data(), n, lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data());
    std::size_t shown = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const float* v = records.data() + 8 * i;
        const obbsat::ref::box_bounds want =
            kind == store_kind::poses
                ? obbsat::ref::bounds_of(obbsat::rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}})
                : obbsat::ref::bounds_of(obbsat::rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
        const bool same = bits_of(want.lo_x) == bits_of(lo_x[i]) && bits_of(want.lo_y) == bits_of(lo_y[i]) &&
                          bits_of(want.hi_x) == bits_of(hi_x[i]) && bits_of(want.hi_y) == bits_of(hi_y[i]);
        if (!same && shown++ < 5) {
            ADD_FAILURE() << what << " record " << i << std::hexfloat << ": want (" << want.lo_x << ", " << want.lo_y
                          << ", " << want.hi_x << ", " << want.hi_y << "), lanes give (" << lo_x[i] << ", " << lo_y[i]
                          << ", " << hi_x[i] << ", " << hi_y[i] << ")";
        }
    }
    EXPECT_EQ(shown, 0u) << what;
    // Nothing past the last record is written.
    EXPECT_EQ(lo_x[n], -7.0f) << what;
    EXPECT_EQ(hi_y[n], -7.0f) << what;
}

class bounds_lanes : public ::testing::TestWithParam<obbsat_test::backend_case> {};

TEST_P(bounds_lanes, equal_the_reference_bit_for_bit) {
    if (!obbsat::cpu_supports(GetParam().id)) {
        GTEST_SKIP() << "this CPU does not run " << obbsat::backend_name(GetParam().id);
    }
    const auto& table = *GetParam().table;
    obbsat::seeded_random random(20261123);
    expect_reference_bounds(table, store_kind::poses, pose_records(random, 400'000), "poses");
    expect_reference_bounds(table, store_kind::corners, corner_records(random, 400'000), "corners");
    for (std::size_t n = 0; n <= 50; ++n) {
        expect_reference_bounds(table, store_kind::poses, pose_records(random, n), "poses, length " + std::to_string(n));
        expect_reference_bounds(table, store_kind::corners, corner_records(random, n),
                                "corners, length " + std::to_string(n));
    }
}

TEST(bounds_lanes_cases, the_cases_reach_infinity_and_signed_zeros) {
    // The inputs must exercise what could differ between lanes and the reference.
    obbsat::seeded_random random(20261123);
    const std::vector<float> poses = pose_records(random, 400'000);
    std::size_t infinite = 0;
    for (std::size_t i = 0; i < poses.size(); i += 8) {
        const float* v = poses.data() + i;
        const auto b = obbsat::ref::bounds_of(obbsat::rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
        infinite += std::isinf(b.hi_x) ? 1u : 0u;
    }
    EXPECT_GT(infinite, 1000u);
    const std::vector<float> corners = corner_records(random, 400'000);
    std::size_t negative_zero_lows = 0;
    for (std::size_t i = 0; i < corners.size(); i += 8) {
        const float* v = corners.data() + i;
        const auto b = obbsat::ref::bounds_of(obbsat::rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
        negative_zero_lows += (b.lo_x == 0.0f && std::signbit(b.lo_x)) ? 1u : 0u;
    }
    EXPECT_GT(negative_zero_lows, 100u);
}


INSTANTIATE_TEST_SUITE_P(backends, bounds_lanes, ::testing::ValuesIn(obbsat_test::backends_here()),
                         obbsat_test::backend_case_name);

}  // namespace
