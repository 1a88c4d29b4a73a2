// The scalar reference of method sat4_double: sat4's steps in double on the
// float input. For rectangles with integer corners below 2^23 every double
// operation of the method is exact (products of at most 24 and 25 bits, sums
// of at most 50), and scaling by a power of two changes no rounding, so on
// those inputs the method must give the exact geometric verdict even where
// float sat4 cannot.
#include "test_support/exact_intersection.hpp"
#include "test_support/float_text.hpp"
#include "test_support/hard_pairs.hpp"
#include "test_support/rect_shapes.hpp"

#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_double.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::point;
using obbsat::rect;
using obbsat::ref::sat4;
using obbsat::ref::sat4_double;
using namespace obbsat::test_support;

struct exact_pair {
    rect a;
    rect b;
    bool meet;
};

/// Integer rectangles touching, one lattice step apart and one step in, at
/// `origin`: the same contacts the hard pairs use, with their exact answer.
std::vector<exact_pair> integer_contact_pairs(point origin) {
    std::vector<exact_pair> out;
    for (int ea = -3; ea <= 3; ++ea) {
        for (int eb = -3; eb <= 3; ++eb) {
            if (ea == 0 && eb == 0) {
                continue;
            }
            for (int k = 1; k <= 3; ++k) {
                const rect a = integer_rect(origin, ea, eb, k);
                for (const auto& c : hard_pairs_detail::integer_contacts(origin, ea, eb, k)) {
                    for (const rect& b : {c.b, translated(c.b, c.outward),
                                          translated(c.b, scaled(c.outward, -1.0f))}) {
                        out.push_back({a, b, convex_quads_meet(a, b)});
                    }
                }
            }
        }
    }
    return out;
}

TEST(sat4_double_ref, agrees_with_sat4_where_float_is_exact) {
    for (const exact_pair& p : integer_contact_pairs({3, -2})) {
        ASSERT_EQ(sat4_double(p.a, p.b), p.meet)
            << "A " << describe(p.a) << "\nB " << describe(p.b);
        ASSERT_EQ(sat4(p.a, p.b), p.meet) << "A " << describe(p.a) << "\nB " << describe(p.b);
    }
}

// Far from the origin float products lose bits and sat4 errs on exact contact;
// in double the same steps stay exact.
TEST(sat4_double_ref, exact_on_integer_rectangles_far_from_the_origin) {
    std::size_t float_errors = 0, pairs = 0;
    for (const point origin :
         {point{4194301, -4194000}, point{-3000000, 2999999}, point{1000001, 7}}) {
        for (const exact_pair& p : integer_contact_pairs(origin)) {
            ++pairs;
            ASSERT_EQ(sat4_double(p.a, p.b), p.meet)
                << "A " << describe(p.a) << "\nB " << describe(p.b);
            ASSERT_EQ(sat4_double(p.b, p.a), p.meet)
                << "swapped: A " << describe(p.a) << "\nB " << describe(p.b);
            float_errors += sat4(p.a, p.b) != p.meet ? 1u : 0u;
        }
    }
    // The offsets are far enough out for float sat4 to err, or this shows nothing.
    EXPECT_GT(float_errors, 0u);
    RecordProperty("sat4_float_errors",
                   std::to_string(float_errors) + " of " + std::to_string(pairs));
}

// Multiplying every coordinate by 2^k is exact and scales every product by
// 2^2k, so the double verdict must not change from 2^-140 (subnormal floats)
// to 2^100 (float products would overflow), while float sat4 underflows or
// overflows at the ends.
TEST(sat4_double_ref, power_of_two_scaling_changes_nothing) {
    const std::vector<exact_pair> base = integer_contact_pairs({1, 2});
    for (const int exponent : {-140, -130, -100, -60, -20, 0, 20, 60, 100}) {
        const float factor = std::ldexp(1.0f, exponent);
        SCOPED_TRACE("scale 2^" + std::to_string(exponent));
        for (const exact_pair& p : base) {
            const rect a = scaled(p.a, factor), b = scaled(p.b, factor);
            ASSERT_EQ(sat4_double(a, b), p.meet) << "A " << describe(a) << "\nB " << describe(b);
        }
    }
}

TEST(sat4_double_ref, overflowing_float_products_are_finite_in_double) {
    // Touching along an edge at 2^100: float sat4 sees inf and NaN scalars.
    const float big = std::ldexp(1.0f, 100);
    const rect a = scaled(axis_aligned(0, 0, 4, 2), big);
    const rect touching = scaled(axis_aligned(4, 0, 7, 2), big);
    const rect apart = scaled(axis_aligned(5, 0, 7, 2), big);
    EXPECT_TRUE(sat4_double(a, touching));
    EXPECT_FALSE(sat4_double(a, apart));
    EXPECT_TRUE(std::isinf(obbsat::ref::scalar_on_axis(a.ur, {4 * big, 0})));
}

// The public steps, composed as the contract lists them, are the method: the
// drawing replays sat4_double through them and must reach the same verdict.
TEST(sat4_double_ref, its_public_steps_composed_give_the_method) {
    using obbsat::ref::double_axis;
    using obbsat::ref::double_extent;
    for (const labelled_pair& p : hard_pairs(500)) {
        double_axis axes[4];
        obbsat::ref::sat4_double_axes(p.a, p.b, axes);
        bool all_overlap = true;
        for (const double_axis axis : axes) {
            const double_extent ea = obbsat::ref::sat4_double_projection(p.a, axis);
            const double_extent eb = obbsat::ref::sat4_double_projection(p.b, axis);
            all_overlap = all_overlap && obbsat::ref::double_extents_overlap(ea, eb);
        }
        ASSERT_EQ(all_overlap, sat4_double(p.a, p.b)) << "A " << describe(p.a) << "\nB " << describe(p.b);
    }
    const rect a = axis_aligned(0, 0, 4, 2);
    const rect b = axis_aligned(1, 5, 3, 9);
    double_axis axes[4];
    obbsat::ref::sat4_double_axes(a, b, axes);
    // A.UR - A.UL, A.UR - A.LR, B.UL - B.LL, B.UL - B.UR, one double subtraction each.
    const double_axis want[4] = {
        {static_cast<double>(a.ur.x) - a.ul.x, static_cast<double>(a.ur.y) - a.ul.y},
        {static_cast<double>(a.ur.x) - a.lr.x, static_cast<double>(a.ur.y) - a.lr.y},
        {static_cast<double>(b.ul.x) - b.ll.x, static_cast<double>(b.ul.y) - b.ll.y},
        {static_cast<double>(b.ul.x) - b.ur.x, static_cast<double>(b.ul.y) - b.ur.y},
    };
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(axes[k].x, want[k].x) << k;
        EXPECT_EQ(axes[k].y, want[k].y) << k;
    }
}

// The picks are min-pick(u, v) = u < v ? u : v and max-pick(u, v) = u > v ? u : v
// folded UL, UR, LR, LL: on equal scalars each returns its second operand, so
// of scalars that are all zero the fold keeps the last one's sign for both
// ends. Picks with their operands swapped would keep the first one's.
TEST(sat4_double_ref, projection_folds_the_picks_in_the_contracts_operand_order) {
    const float z = 0.0f;
    const rect last_negative{{z, z}, {z, z}, {z, z}, {-z, -z}};
    const obbsat::ref::double_extent e = obbsat::ref::sat4_double_projection(last_negative, {1.0, 1.0});
    EXPECT_EQ(e.min, 0.0);
    EXPECT_TRUE(std::signbit(e.min));
    EXPECT_TRUE(std::signbit(e.max));
    const rect first_negative{{-z, -z}, {z, z}, {z, z}, {z, z}};
    const obbsat::ref::double_extent f = obbsat::ref::sat4_double_projection(first_negative, {1.0, 1.0});
    EXPECT_FALSE(std::signbit(f.min));
    EXPECT_FALSE(std::signbit(f.max));
}

}  // namespace
