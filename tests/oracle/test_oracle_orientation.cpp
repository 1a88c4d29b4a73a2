// The exact orientation predicate against GMP rationals, on triples built to
// sit on or within a few float steps of collinearity, across the whole float
// range (subnormals to 1e38), where a double evaluation gets signs wrong.
#include <obbsat/oracle/orientation.hpp>

#include <obbsat/scene.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using obbsat::point;
using obbsat::oracle::orientation;
using obbsat::oracle::orientation_exact;
using obbsat::oracle::sign_of_exact_sum;

int rational_orientation(point p, point q, point r) {
    auto q_of = [](float v) { return mpq_class(static_cast<double>(v)); };
    const mpq_class det = (q_of(q.x) - q_of(p.x)) * (q_of(r.y) - q_of(p.y)) -
                          (q_of(q.y) - q_of(p.y)) * (q_of(r.x) - q_of(p.x));
    return sgn(det);
}

// The determinant in plain double, as a first attempt would compute it.
int naive_orientation(point p, point q, point r) {
    const double det = (static_cast<double>(q.x) - p.x) * (static_cast<double>(r.y) - p.y) -
                       (static_cast<double>(q.y) - p.y) * (static_cast<double>(r.x) - p.x);
    return (det > 0) - (det < 0);
}

std::string show(point p) {
    char text[64];
    std::snprintf(text, sizeof text, "(%a, %a)", static_cast<double>(p.x), static_cast<double>(p.y));
    return text;
}

float step(float v, int steps) {
    for (; steps > 0; --steps) v = std::nextafter(v, INFINITY);
    for (; steps < 0; ++steps) v = std::nextafter(v, -INFINITY);
    return v;
}

// A float with a random significand and a binary exponent in [lo, hi], random sign.
float random_float(obbsat::seeded_random& random, int lo, int hi) {
    const int exponent = lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
    const float magnitude = std::ldexp(random.uniform(1.0f, 2.0f), exponent);
    return (random.next() & 1u) != 0 ? magnitude : -magnitude;
}

void expect_exact(point p, point q, point r) {
    const int want = rational_orientation(p, q, r);
    ASSERT_EQ(orientation(p, q, r), want) << show(p) << " " << show(q) << " " << show(r);
    ASSERT_EQ(orientation_exact(p, q, r), want) << show(p) << " " << show(q) << " " << show(r);
}

TEST(orientation, hand_cases) {
    EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
    EXPECT_EQ(orientation({0, 0}, {0, 1}, {1, 0}), -1);
    EXPECT_EQ(orientation({0, 0}, {1, 1}, {2, 2}), 0);
    EXPECT_EQ(orientation({0, 0}, {0, 0}, {5, 7}), 0);
    EXPECT_EQ(orientation({3, 4}, {3, 4}, {3, 4}), 0);
    // The smallest subnormal against the largest float: no double product of
    // rounded differences can hold this determinant's sign reliably.
    const float tiny = std::numeric_limits<float>::denorm_min();
    const float big = FLT_MAX;
    expect_exact({0, 0}, {big, big}, {big, std::nextafter(big, 0.0f)});
    expect_exact({tiny, 0}, {big, big}, {-big, -big});
    // Exactly 2 * tiny * big > 0, where plain double arithmetic finds 0.
    EXPECT_EQ(orientation({tiny, 0}, {big, big}, {-big, -big}), 1);
    EXPECT_EQ(naive_orientation({tiny, 0}, {big, big}, {-big, -big}), 0);
    expect_exact({tiny, tiny}, {0, 0}, {-tiny, -tiny});
    expect_exact({tiny, 0}, {0, tiny}, {-tiny, 2 * tiny});
    expect_exact({-big, big}, {big, -big}, {tiny, -tiny});
    expect_exact({-big, big}, {big, -big}, {tiny, 0});
}

TEST(orientation, is_antisymmetric_and_cyclic) {
    obbsat::seeded_random random(11);
    for (int i = 0; i < 20000; ++i) {
        const point p{random_float(random, -20, 20), random_float(random, -20, 20)};
        const point q{random_float(random, -20, 20), random_float(random, -20, 20)};
        const point r{p.x + (q.x - p.x) * 0.5f, p.y + (q.y - p.y) * 0.5f};
        const int s = orientation(p, q, r);
        ASSERT_EQ(orientation(q, r, p), s);
        ASSERT_EQ(orientation(r, p, q), s);
        ASSERT_EQ(orientation(q, p, r), -s);
        ASSERT_EQ(orientation(p, r, q), -s);
    }
}

TEST(orientation, near_collinear_triples_across_the_float_range_match_rationals) {
    obbsat::seeded_random random(2024);
    int nonzero = 0, naive_wrong = 0;
    // Exponent windows: subnormal, tiny, unit, large, huge, and mixed spans.
    const int windows[][2] = {{-149, -126}, {-100, -80}, {-10, 10}, {20, 40}, {100, 127}, {-149, 127}};
    for (const auto& window : windows) {
        for (int i = 0; i < 20000; ++i) {
            const point p{random_float(random, window[0], window[1]), random_float(random, window[0], window[1])};
            const point q{random_float(random, window[0], window[1]), random_float(random, window[0], window[1])};
            const float t = random.uniform(-2.0f, 3.0f);
            // r on the line through p and q before rounding, then 0..2 steps away.
            point r{static_cast<float>(static_cast<double>(p.x) + t * (static_cast<double>(q.x) - p.x)),
                    static_cast<float>(static_cast<double>(p.y) + t * (static_cast<double>(q.y) - p.y))};
            if (!std::isfinite(r.x) || !std::isfinite(r.y)) {
                continue;
            }
            r = point{step(r.x, static_cast<int>(random.below(5)) - 2),
                      step(r.y, static_cast<int>(random.below(5)) - 2)};
            if (!std::isfinite(r.x) || !std::isfinite(r.y)) {
                continue;
            }
            expect_exact(p, q, r);
            const int want = rational_orientation(p, q, r);
            nonzero += want != 0;
            naive_wrong += naive_orientation(p, q, r) != want;
        }
    }
    std::printf("[ orient   ] plain double got %d of these signs wrong\n", naive_wrong);
    EXPECT_GT(nonzero, 50000);
}

TEST(orientation, exactly_collinear_triples_and_their_one_step_neighbours) {
    // p, p + d, p + k d with small integer significands times 2^e: exact in
    // float and exactly collinear; then r moved by one float step.
    obbsat::seeded_random random(8);
    int zero = 0;
    for (int i = 0; i < 50000; ++i) {
        const int exponent = static_cast<int>(random.below(250)) - 149;
        auto scaled = [&](std::uint64_t bound, std::int64_t shift) {
            return std::ldexp(static_cast<float>(static_cast<std::int64_t>(random.below(bound)) - shift), exponent);
        };
        const point p{scaled(1u << 20, 1 << 19), scaled(1u << 20, 1 << 19)};
        const point d{scaled(16, 8), scaled(16, 8)};
        const auto k = static_cast<float>(static_cast<int>(random.below(9)) - 4);
        const point q{p.x + d.x, p.y + d.y};
        point r{p.x + k * d.x, p.y + k * d.y};
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(r.x) || !std::isfinite(r.y)) {
            continue;
        }
        expect_exact(p, q, r);
        zero += rational_orientation(p, q, r) == 0;
        r = point{step(r.x, static_cast<int>(random.below(3)) - 1), step(r.y, static_cast<int>(random.below(3)) - 1)};
        if (std::isfinite(r.x) && std::isfinite(r.y)) {
            expect_exact(p, q, r);
        }
    }
    EXPECT_GT(zero, 20000);
}

TEST(orientation, lattice_points_on_a_line_are_collinear_far_from_the_origin) {
    // Points k * (3, 7) + offset with float-exact coordinates up to 2^24.
    obbsat::seeded_random random(5);
    for (int i = 0; i < 10000; ++i) {
        const auto base_x = static_cast<float>(random.below(1u << 22));
        const auto base_y = static_cast<float>(random.below(1u << 22));
        const auto k1 = static_cast<float>(random.below(1000));
        const auto k2 = static_cast<float>(random.below(1000));
        const point p{base_x, base_y};
        const point q{base_x + 3 * k1, base_y + 7 * k1};
        const point r{base_x + 3 * k2, base_y + 7 * k2};
        ASSERT_EQ(orientation(p, q, r), 0);
        ASSERT_EQ(orientation(p, q, point{r.x + 1, r.y}), k1 == 0 ? 0 : -1);
    }
}

// Sums of products of two floats, as the drawing's exact dot products build
// them: terms that cancel to zero, to one part in 2^200, or not at all.
TEST(sign_of_exact_sum, matches_rationals_on_cancelling_products_of_floats) {
    obbsat::seeded_random random(9);
    for (int i = 0; i < 20000; ++i) {
        const int count = 1 + static_cast<int>(random.below(obbsat::oracle::exact_sum_max_terms));
        std::vector<double> terms;
        mpq_class exact = 0;
        for (int t = 0; t < count; ++t) {
            const double u = random_float(random, -140, 120);
            const double v = random_float(random, -140, 120);
            // Half the time a term cancels an earlier one but for a tiny rest.
            double term = u * v;
            if (t > 0 && (random.next() & 1u) != 0) {
                term = -terms[random.below(static_cast<std::uint64_t>(t))];
                if ((random.next() & 3u) == 0) {
                    term += std::ldexp(term, -52);
                }
            }
            terms.push_back(term);
            exact += mpq_class(term);
        }
        ASSERT_EQ(sign_of_exact_sum(terms.data(), count), sgn(exact)) << "case " << i;
    }
    const double none[1] = {0.0};
    EXPECT_EQ(sign_of_exact_sum(none, 0), 0);
    const double tiny_rest[3] = {0x1p100, 0x1p-140, -0x1p100};
    EXPECT_EQ(sign_of_exact_sum(tiny_rest, 3), 1);
    const double too_many[obbsat::oracle::exact_sum_max_terms + 1] = {};
    EXPECT_THROW(sign_of_exact_sum(too_many, obbsat::oracle::exact_sum_max_terms + 1),
                 std::invalid_argument);
    EXPECT_THROW(sign_of_exact_sum(too_many, -1), std::invalid_argument);
}

// Products of three floats, each split into its rounded double and the exact
// rest (fma), as the pose oracle builds them: factors from subnormal to near the
// largest float, so the terms span 2^-447 to 2^384. Half of the products cancel
// an earlier one, exactly or but for one float step of one factor.
TEST(sign_of_exact_sum, matches_rationals_on_split_products_of_three_floats) {
    obbsat::seeded_random random(10);
    for (int i = 0; i < 20000; ++i) {
        const int count = 1 + static_cast<int>(random.below(obbsat::oracle::exact_sum_max_terms / 2));
        std::vector<std::array<float, 3>> products;
        std::vector<double> terms;
        mpq_class exact = 0;
        for (int t = 0; t < count; ++t) {
            std::array<float, 3> f{};
            if (t > 0 && (random.next() & 1u) != 0) {
                f = products[random.below(static_cast<std::uint64_t>(t))];
                f[0] = -f[0];
                if ((random.next() & 3u) == 0) {
                    const std::size_t k = random.below(3);
                    f[k] = step(f[k], 1);
                }
            } else {
                for (float& x : f) {
                    x = random_float(random, -149, 126);
                }
            }
            products.push_back(f);
            const double two = static_cast<double>(f[0]) * f[1];
            const double high = two * f[2];
            terms.push_back(high);
            terms.push_back(std::fma(two, static_cast<double>(f[2]), -high));
            exact += mpq_class(static_cast<double>(f[0])) * mpq_class(static_cast<double>(f[1])) *
                     mpq_class(static_cast<double>(f[2]));
        }
        ASSERT_EQ(sign_of_exact_sum(terms.data(), static_cast<int>(terms.size())), sgn(exact))
            << "case " << i;
    }
}

}  // namespace
