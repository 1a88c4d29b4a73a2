// sign_of_product_sum against GMP rationals: random products of one to three
// doubles over the whole finite range (subnormals and 1e308 included), sums that
// cancel to zero or to a last bit far below the largest term, and bad arguments.
#include <obbsat/oracle/product_sum.hpp>
#include <obbsat/scene.hpp>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using obbsat::oracle::product_sum_max_terms;
using obbsat::oracle::product_term;
using obbsat::oracle::sign_of_product_sum;

int gmp_sign(const product_term* terms, int count) {
    mpq_class sum = 0;
    for (int t = 0; t < count; ++t) {
        mpq_class product = 1;
        for (const double f : terms[t].factor) {
            product *= mpq_class(f);
        }
        sum += product;
    }
    return sgn(sum);
}

std::string show(const product_term* terms, int count) {
    std::string text;
    char buffer[120];
    for (int t = 0; t < count; ++t) {
        std::snprintf(buffer, sizeof buffer, "(%a * %a * %a) ", terms[t].factor[0], terms[t].factor[1],
                      terms[t].factor[2]);
        text += buffer;
    }
    return text;
}

// A double with a random sign, 53 random bits and an exponent in [lo, hi]; a
// subnormal when the exponent is below -1022 (then with fewer bits).
double random_double(obbsat::seeded_random& random, int lo, int hi) {
    const double m = static_cast<double>(random.next() >> 11) * 0x1p-54 + 0.5;  // in [0.5, 1)
    const int e = lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
    const double v = std::ldexp(m, e);
    return random.below(2) == 0 ? v : -v;
}

void expect_gmp_sign(const product_term* terms, int count) {
    ASSERT_EQ(sign_of_product_sum(terms, count), gmp_sign(terms, count)) << show(terms, count);
}

TEST(product_sum, random_products_over_the_whole_range) {
    obbsat::seeded_random random(11);
    product_term terms[product_sum_max_terms];
    for (int round = 0; round < 20000 && !::testing::Test::HasFailure(); ++round) {
        const int count = 1 + static_cast<int>(random.below(product_sum_max_terms));
        for (int t = 0; t < count; ++t) {
            for (double& f : terms[t].factor) {
                f = random.below(6) == 0 ? 1.0 : random_double(random, -1073, 1024);
            }
        }
        expect_gmp_sign(terms, count);
    }
}

TEST(product_sum, sums_that_cancel_down_to_the_last_bit) {
    // Every term matched by its negation with one factor moved by one ulp, or not
    // moved at all: the sum is zero or a few last bits of products far larger.
    obbsat::seeded_random random(12);
    product_term terms[product_sum_max_terms];
    int zeros = 0;
    for (int round = 0; round < 20000 && !::testing::Test::HasFailure(); ++round) {
        const int pairs = 1 + static_cast<int>(random.below(product_sum_max_terms / 2));
        const int lo = random.below(2) == 0 ? -1073 : -40;
        const int hi = random.below(2) == 0 ? 1024 : 40;
        for (int t = 0; t < pairs; ++t) {
            for (double& f : terms[2 * t].factor) {
                f = random_double(random, lo, hi);
            }
            terms[2 * t + 1] = terms[2 * t];
            terms[2 * t + 1].factor[0] = -terms[2 * t + 1].factor[0];
            if (random.below(3) == 0) {
                double& moved = terms[2 * t + 1].factor[random.below(3)];
                moved = std::nextafter(moved, random.below(2) == 0 ? INFINITY : -INFINITY);
            }
        }
        const int count = 2 * pairs;
        zeros += gmp_sign(terms, count) == 0 ? 1 : 0;
        expect_gmp_sign(terms, count);
    }
    EXPECT_GT(zeros, 1000);
}

TEST(product_sum, extremes_of_the_range) {
    const double big = std::numeric_limits<double>::max();
    const double tiny = std::numeric_limits<double>::denorm_min();
    const product_term cubes[3] = {{{big, big, big}}, {{-big, big, big}}, {{tiny, tiny, tiny}}};
    EXPECT_EQ(sign_of_product_sum(cubes, 3), 1);  // only the tiny cube is left
    const product_term tiny_against_big[2] = {{{big, big, -big}}, {{tiny, 1.0, 1.0}}};
    EXPECT_EQ(sign_of_product_sum(tiny_against_big, 2), -1);
    const product_term nothing[1] = {{{0.0, big, big}}};
    EXPECT_EQ(sign_of_product_sum(nothing, 1), 0);
    EXPECT_EQ(sign_of_product_sum(nothing, 0), 0);
}

TEST(product_sum, refuses_bad_arguments) {
    product_term terms[product_sum_max_terms + 1] = {};
    EXPECT_THROW(sign_of_product_sum(terms, product_sum_max_terms + 1), std::invalid_argument);
    EXPECT_THROW(sign_of_product_sum(terms, -1), std::invalid_argument);
    terms[0] = product_term{{1.0, std::numeric_limits<double>::infinity(), 1.0}};
    EXPECT_THROW(sign_of_product_sum(terms, 1), std::invalid_argument);
    terms[0] = product_term{{1.0, std::nan(""), 1.0}};
    EXPECT_THROW(sign_of_product_sum(terms, 1), std::invalid_argument);
}

}  // namespace
