// The double rows' float bounds of the scene queries (kernel/scene/outward_bounds.hpp)
// against the reference (obbsat/ref/bounds64.hpp), bit for bit: random rows,
// rows at UTM-like coordinates, and the cases where rounding outward steps
// through zero, to and from infinity, and between subnormals.
#include "scene/outward_bounds.hpp"

#include <obbsat/ref/bounds64.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using obbsat::detail::double_bounds_run;

/// Stage 2 of a run, into arrays of its own.
struct float_bounds_run {
    float lo_x[double_bounds_run::size];
    float lo_y[double_bounds_run::size];
    float hi_x[double_bounds_run::size];
    float hi_y[double_bounds_run::size];
};

void round_run(const double_bounds_run& staged, std::size_t count, float_bounds_run& out) {
    obbsat::detail::round_bounds_outward(staged, count, out.lo_x, out.lo_y, out.hi_x, out.hi_y);
}

std::uint32_t bits_of(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

/// Rounds `values` outward both ways in runs and compares each float with the reference's.
void expect_reference_rounding(const std::vector<double>& values) {
    for (std::size_t begin = 0; begin < values.size(); begin += double_bounds_run::size) {
        const std::size_t count = std::min(values.size() - begin, double_bounds_run::size);
        float down[double_bounds_run::size];
        float up[double_bounds_run::size];
        obbsat::detail::round_outward<false>(values.data() + begin, count, down);
        obbsat::detail::round_outward<true>(values.data() + begin, count, up);
        for (std::size_t r = 0; r < count; ++r) {
            const double d = values[begin + r];
            EXPECT_EQ(bits_of(down[r]), bits_of(obbsat::ref::float_at_most(d))) << "at most " << d;
            EXPECT_EQ(bits_of(up[r]), bits_of(obbsat::ref::float_at_least(d))) << "at least " << d;
        }
    }
}

void expect_same_bounds(const obbsat::ref::box_bounds& want, const float_bounds_run& got, std::size_t r) {
    EXPECT_EQ(bits_of(got.lo_x[r]), bits_of(want.lo_x)) << "row " << r;
    EXPECT_EQ(bits_of(got.lo_y[r]), bits_of(want.lo_y)) << "row " << r;
    EXPECT_EQ(bits_of(got.hi_x[r]), bits_of(want.hi_x)) << "row " << r;
    EXPECT_EQ(bits_of(got.hi_y[r]), bits_of(want.hi_y)) << "row " << r;
}

TEST(outward_bounds, rounding_is_the_references_at_the_edges) {
    const double flt_max = std::numeric_limits<float>::max();
    const double tiny = std::numeric_limits<float>::denorm_min();
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> values = {0.0,         -0.0,       1e-50,        -1e-50,        tiny,        -tiny,
                                  tiny / 2,    -tiny / 2,  tiny * 1.5,   -tiny * 1.5,   flt_max,     -flt_max,
                                  flt_max * 1.0000001,     -flt_max * 1.0000001,        1e300,       -1e300,
                                  inf,         -inf,       1.0,          -1.0,          0.1,         -0.1,
                                  5712345.5,   -5712345.5, 500000.125,   0x1p-126,      -0x1p-126,   0x1p-149};
    // Each float's neighbours in double: on it, just above and just below.
    for (const float f : {1.0f, -1.0f, 3.0e7f, -3.0e7f, 1e-40f, -1e-40f, 0x1p-126f}) {
        const double d = f;
        values.push_back(d);
        values.push_back(std::nextafter(d, inf));
        values.push_back(std::nextafter(d, -inf));
    }
    expect_reference_rounding(values);
}

TEST(outward_bounds, rounding_is_the_references_on_random_doubles) {
    std::mt19937_64 rng(7);
    std::vector<double> values(3000);
    std::uniform_real_distribution<double> exponent(-160.0, 140.0);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (double& v : values) {
        v = unit(rng) * std::exp2(exponent(rng));
    }
    expect_reference_rounding(values);
}

TEST(outward_bounds, pose_rows_give_the_reference_bounds) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> at(-3.0, 3.0);
    std::uniform_real_distribution<double> half(0.0, 2.0);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    // Rows 6 doubles apart, as rect_pose64 in a vector; some at UTM-like coordinates, one degenerate.
    std::vector<obbsat::rect_pose64> poses;
    for (int i = 0; i < 600; ++i) {
        const double a = angle(rng);
        const double x = (i % 2 == 0 ? 500000.125 : 0.0) + at(rng);
        const double y = (i % 3 == 0 ? 5712345.5 : 0.0) + at(rng);
        poses.push_back({{x, y}, {half(rng), half(rng)}, {std::cos(a), std::sin(a)}});
    }
    poses.push_back({{0.0, -0.0}, {0.0, 0.0}, {1.0, 0.0}});
    poses.push_back({{1e300, -1e300}, {1e300, 1e300}, {0.6, 0.8}});
    for (std::size_t begin = 0; begin < poses.size(); begin += double_bounds_run::size) {
        const std::size_t count = std::min(poses.size() - begin, double_bounds_run::size);
        double_bounds_run staged;
        float_bounds_run got;
        obbsat::detail::stage_pose_bounds(&poses[begin].center.x, 6, count, staged);
        round_run(staged, count, got);
        for (std::size_t r = 0; r < count; ++r) {
            expect_same_bounds(obbsat::ref::bounds_of(poses[begin + r]), got, r);
        }
    }
}

TEST(outward_bounds, corner_rows_give_the_reference_bounds) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> at(-1e6, 1e6);
    std::vector<obbsat::rect64> rects;
    for (int i = 0; i < 300; ++i) {
        rects.push_back({{at(rng), at(rng)}, {at(rng), at(rng)}, {at(rng), at(rng)}, {at(rng), at(rng)}});
    }
    double_bounds_run staged;
    float_bounds_run got;
    const std::size_t count = std::min(rects.size(), double_bounds_run::size);
    obbsat::detail::stage_corner_bounds(&rects[0].ul.x, 8, count, staged);
    round_run(staged, count, got);
    for (std::size_t r = 0; r < count; ++r) {
        expect_same_bounds(obbsat::ref::bounds_of(rects[r]), got, r);
    }
}

}  // namespace
