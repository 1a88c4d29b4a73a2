// The scalar reference of method sat4 against hand-worked cases, the
// article's figures, and an exact integer oracle on rectangles whose float
// arithmetic is exact. Every comparison is exact: these inputs are chosen so
// that no operation rounds, or so that the rounding is the point of the test.
#include "test_support/exact_intersection.hpp"
#include "test_support/float_text.hpp"
#include "test_support/rect_shapes.hpp"

#include <obbsat/ref/sat4.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::point;
using obbsat::rect;
using obbsat::ref::extent;
using obbsat::ref::extents_overlap;
using obbsat::ref::max_pick;
using obbsat::ref::min_pick;
using obbsat::ref::project_rect;
using obbsat::ref::sat4;
using obbsat::ref::scalar_on_axis;
using namespace obbsat::test_support;

constexpr float nan_value = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_value = std::numeric_limits<float>::infinity();

bool identical_bits(float u, float v) {
    std::uint32_t bits_u = 0, bits_v = 0;
    std::memcpy(&bits_u, &u, sizeof u);
    std::memcpy(&bits_v, &v, sizeof v);
    return bits_u == bits_v;
}

bool aabbs_overlap(const rect& a, const rect& b) {
    auto lo = [](const rect& r, float point::*c) {
        return std::fmin(std::fmin(r.ul.*c, r.ur.*c), std::fmin(r.lr.*c, r.ll.*c));
    };
    auto hi = [](const rect& r, float point::*c) {
        return std::fmax(std::fmax(r.ul.*c, r.ur.*c), std::fmax(r.lr.*c, r.ll.*c));
    };
    return lo(b, &point::x) <= hi(a, &point::x) && hi(b, &point::x) >= lo(a, &point::x) &&
           lo(b, &point::y) <= hi(a, &point::y) && hi(b, &point::y) >= lo(a, &point::y);
}

bool any_corner_inside(const rect& quad, const rect& other) {
    const auto q = lattice_corners(quad);
    for (const auto& p : lattice_corners(other)) {
        if (inside_or_on(q, p)) {
            return true;
        }
    }
    return false;
}

// Every labelling of the same pair that cannot change an exact verdict: both
// windings and every starting corner, for A and B, in both orders.
std::vector<std::pair<rect, rect>> exact_variants(const rect& a, const rect& b) {
    std::vector<rect> forms_a, forms_b;
    for (const rect& base : {a, reversed_winding(a)}) {
        rect r = base;
        for (int turns = 0; turns < 4; ++turns, r = relabelled(r)) {
            forms_a.push_back(r);
        }
    }
    for (const rect& base : {b, reversed_winding(b)}) {
        rect r = base;
        for (int turns = 0; turns < 4; ++turns, r = relabelled(r)) {
            forms_b.push_back(r);
        }
    }
    std::vector<std::pair<rect, rect>> out;
    for (const rect& fa : forms_a) {
        for (const rect& fb : forms_b) {
            out.emplace_back(fa, fb);
            out.emplace_back(fb, fa);
        }
    }
    return out;
}

// Asserts sat4 gives `expected` for every exact variant of (a, b).
void expect_verdict_in_every_labelling(const rect& a, const rect& b, bool expected) {
    for (const auto& [fa, fb] : exact_variants(a, b)) {
        EXPECT_EQ(sat4(fa, fb), expected) << "A " << describe(fa) << "\nB " << describe(fb);
    }
}

TEST(sat4_ref, article_example_scalar_of_corner_2_6_on_axis_3_4_is_30) {
    const point corner{2.0f, 6.0f};
    const point axis{3.0f, 4.0f};
    const float scalar = scalar_on_axis(corner, axis);
    EXPECT_EQ(scalar, 30.0f);
    const float axis_norm_squared = scalar_on_axis(axis, axis);
    EXPECT_EQ(axis_norm_squared, 25.0f);
    // The article's projection (30 / 25) * axis: (scalar * axis) / |axis|^2 is
    // 90 / 25 and 120 / 25, one correctly rounded division each.
    const double projected_x = static_cast<double>(scalar) * static_cast<double>(axis.x) /
                               static_cast<double>(axis_norm_squared);
    const double projected_y = static_cast<double>(scalar) * static_cast<double>(axis.y) /
                               static_cast<double>(axis_norm_squared);
    EXPECT_EQ(projected_x, 3.6);
    EXPECT_EQ(projected_y, 4.8);
}

TEST(sat4_ref, scalar_rounds_each_product_then_the_sum_without_fusing) {
    // x * ax = 1 + 2^-11 + 2^-24 rounds (ties to even) to 1 + 2^-11, which the
    // y product cancels exactly: 0 unfused, 2^-24 if fused into one FMA.
    const float one_plus = 1.0f + 0x1p-12f;
    const point corner{one_plus, -1.0f};
    const point axis{one_plus, 1.0f + 0x1p-11f};
    EXPECT_EQ(scalar_on_axis(corner, axis), 0.0f) << hex_float(scalar_on_axis(corner, axis));
}

TEST(sat4_ref, axis_between_subtracts_from_from_to) {
    const point axis = obbsat::ref::axis_between(point{1.5f, -2.0f}, point{4.0f, 3.0f});
    EXPECT_EQ(axis.x, 2.5f);
    EXPECT_EQ(axis.y, 5.0f);
}

TEST(sat4_ref, sat4_axes_are_the_articles_four_in_order) {
    const rect a{{0, 1}, {2, 3}, {5, -1}, {1, -4}};
    const rect b{{10, 20}, {13, 24}, {17, 21}, {14, 17}};
    point axes[4];
    obbsat::ref::sat4_axes(a, b, axes);
    // Axis1 = A.UR - A.UL, Axis2 = A.UR - A.LR, Axis3 = B.UL - B.LL, Axis4 = B.UL - B.UR.
    const point expected[4] = {{2, 2}, {-3, 4}, {-4, 3}, {-3, -4}};
    for (unsigned k = 0; k < 4; ++k) {
        EXPECT_EQ(axes[k].x, expected[k].x) << "axis " << k + 1;
        EXPECT_EQ(axes[k].y, expected[k].y) << "axis " << k + 1;
    }
}

TEST(sat4_ref, min_pick_is_u_less_than_v_then_u_else_v) {
    EXPECT_EQ(min_pick(1.0f, 2.0f), 1.0f);
    EXPECT_EQ(min_pick(2.0f, 1.0f), 1.0f);
    EXPECT_EQ(min_pick(-inf_value, 1.0f), -inf_value);
    EXPECT_EQ(min_pick(1.0f, inf_value), 1.0f);
    // NaN in either place: the comparison is false, so v is returned.
    EXPECT_EQ(min_pick(nan_value, 1.0f), 1.0f);
    EXPECT_TRUE(std::isnan(min_pick(1.0f, nan_value)));
    EXPECT_TRUE(std::isnan(min_pick(nan_value, nan_value)));
    // Equal operands (signed zeros compare equal): v is returned.
    EXPECT_TRUE(identical_bits(min_pick(-0.0f, 0.0f), 0.0f));
    EXPECT_TRUE(identical_bits(min_pick(0.0f, -0.0f), -0.0f));
}

TEST(sat4_ref, max_pick_is_u_greater_than_v_then_u_else_v) {
    EXPECT_EQ(max_pick(1.0f, 2.0f), 2.0f);
    EXPECT_EQ(max_pick(2.0f, 1.0f), 2.0f);
    EXPECT_EQ(max_pick(inf_value, 1.0f), inf_value);
    EXPECT_EQ(max_pick(nan_value, 1.0f), 1.0f);
    EXPECT_TRUE(std::isnan(max_pick(1.0f, nan_value)));
    EXPECT_TRUE(std::isnan(max_pick(nan_value, nan_value)));
    EXPECT_TRUE(identical_bits(max_pick(-0.0f, 0.0f), 0.0f));
    EXPECT_TRUE(identical_bits(max_pick(0.0f, -0.0f), -0.0f));
}

TEST(sat4_ref, project_rect_folds_ul_ur_lr_ll_so_a_nan_drops_what_came_before) {
    // On axis (1, 0) the scalar of a corner is its x (y * 0 adds a zero).
    const point axis{1.0f, 0.0f};
    auto with_x = [](float ul, float ur, float lr, float ll) {
        return rect{{ul, 0.0f}, {ur, 0.0f}, {lr, 0.0f}, {ll, 0.0f}};
    };
    const extent plain = project_rect(with_x(3.0f, -1.0f, 2.0f, 0.5f), axis);
    EXPECT_EQ(plain.min, -1.0f);
    EXPECT_EQ(plain.max, 3.0f);

    // NaN first: pick(NaN, s_UR) = s_UR, the NaN vanishes.
    const extent nan_first = project_rect(with_x(nan_value, 1.0f, 2.0f, 3.0f), axis);
    EXPECT_EQ(nan_first.min, 1.0f);
    EXPECT_EQ(nan_first.max, 3.0f);
    // NaN second: pick(s_UL, NaN) = NaN, then pick(NaN, s_LR) = s_LR: s_UL is lost.
    const extent nan_second = project_rect(with_x(1.0f, nan_value, 2.0f, 3.0f), axis);
    EXPECT_EQ(nan_second.min, 2.0f);
    EXPECT_EQ(nan_second.max, 3.0f);
    // NaN last: the fold ends on pick(m, NaN) = NaN.
    const extent nan_last = project_rect(with_x(1.0f, 2.0f, 3.0f, nan_value), axis);
    EXPECT_TRUE(std::isnan(nan_last.min));
    EXPECT_TRUE(std::isnan(nan_last.max));
}

TEST(sat4_ref, project_rect_of_overflowing_products_gives_inf_and_nan) {
    // 1e30 * 1e30 overflows; (+inf) + (-inf) at UR is NaN.
    const float huge = 1.0e30f;
    const rect r{{huge, huge}, {huge, -huge}, {-huge, -huge}, {0.0f, 0.0f}};
    const point axis{huge, huge};
    EXPECT_EQ(scalar_on_axis(r.ul, axis), inf_value);
    EXPECT_TRUE(std::isnan(scalar_on_axis(r.ur, axis)));
    EXPECT_EQ(scalar_on_axis(r.lr, axis), -inf_value);
    const extent e = project_rect(r, axis);
    // min: pick(pick(pick(inf, NaN), -inf), 0) = pick(pick(NaN, -inf), 0) = pick(-inf, 0) = -inf.
    EXPECT_EQ(e.min, -inf_value);
    // max: pick(pick(pick(inf, NaN), -inf), 0) = pick(pick(NaN, -inf), 0) = pick(-inf, 0) = 0.
    EXPECT_EQ(e.max, 0.0f);
}

TEST(sat4_ref, extents_overlap_when_they_share_at_least_one_point) {
    EXPECT_TRUE(extents_overlap({0, 2}, {1, 3}));
    EXPECT_TRUE(extents_overlap({1, 3}, {0, 2}));
    EXPECT_TRUE(extents_overlap({0, 10}, {2, 3}));  // b inside a
    EXPECT_TRUE(extents_overlap({2, 3}, {0, 10}));  // a inside b
    // Touching: equal bounds overlap.
    EXPECT_TRUE(extents_overlap({0, 1}, {1, 2}));
    EXPECT_TRUE(extents_overlap({1, 2}, {0, 1}));
    EXPECT_TRUE(extents_overlap({1, 1}, {1, 1}));
    // One float step apart does not.
    EXPECT_FALSE(extents_overlap({0, 1}, {std::nextafter(1.0f, 2.0f), 2}));
    EXPECT_FALSE(extents_overlap({std::nextafter(1.0f, 2.0f), 2}, {0, 1}));
    EXPECT_FALSE(extents_overlap({0, 1}, {2, 3}));
    EXPECT_FALSE(extents_overlap({2, 3}, {0, 1}));
    // Ordered comparisons: any NaN bound that is compared makes the test false.
    EXPECT_FALSE(extents_overlap({0, nan_value}, {0, 1}));
    EXPECT_FALSE(extents_overlap({nan_value, 1}, {0, 1}));
    EXPECT_FALSE(extents_overlap({0, 1}, {nan_value, 1}));
    EXPECT_FALSE(extents_overlap({0, 1}, {0, nan_value}));
    EXPECT_TRUE(extents_overlap({-inf_value, inf_value}, {0, 1}));
}

TEST(sat4_ref, article_cross_collision_collides_with_no_corner_inside_the_other) {
    // Two long thin rectangles crossing like a plus sign, axis-aligned and turned.
    const rect across = axis_aligned(-10, -1, 10, 1);
    const rect upright = axis_aligned(-1, -10, 1, 10);
    const rect turned_across = from_edges({-20, -35}, {48, 64}, {-8, 6});
    const rect turned_upright = from_edges({29, -28}, {-64, 48}, {6, 8});
    for (const auto& [a, b] :
         {std::pair{across, upright}, std::pair{turned_across, turned_upright}}) {
        ASSERT_FALSE(any_corner_inside(a, b));
        ASSERT_FALSE(any_corner_inside(b, a));
        ASSERT_TRUE(convex_quads_meet(a, b));
        expect_verdict_in_every_labelling(a, b, true);
    }
}

TEST(sat4_ref, separated_turned_rectangles_whose_bounds_overlap_do_not_collide) {
    // The article's motivating figure: an axis-aligned bounds test says yes.
    const rect diamond{{0, 2}, {2, 0}, {0, -2}, {-2, 0}};
    const rect next_diamond = translated(diamond, {3, 3});
    const rect slanted = from_edges({0, 0}, {10, 10}, {-1, 1});
    const rect parallel_slanted = translated(slanted, {3, -1});
    for (const auto& [a, b] :
         {std::pair{diamond, next_diamond}, std::pair{slanted, parallel_slanted}}) {
        ASSERT_TRUE(aabbs_overlap(a, b));
        ASSERT_FALSE(convex_quads_meet(a, b));
        expect_verdict_in_every_labelling(a, b, false);
    }
}

TEST(sat4_ref, touching_axis_aligned_integer_rectangles_collide_and_one_unit_apart_separate) {
    const rect a = axis_aligned(0, 0, 4, 2);
    const rect corner_diamond{{4, 1}, {5, 2}, {6, 1}, {5, 0}};  // its left corner on A's right edge
    const std::pair<const char*, rect> touching[] = {
        {"edge on full edge", axis_aligned(4, 0, 7, 2)},
        {"edge on part of an edge", axis_aligned(4, 1, 7, 5)},
        {"edge on edge, top", axis_aligned(1, 2, 3, 6)},
        {"corner on corner", axis_aligned(4, 2, 6, 5)},
        {"corner on corner, below left", axis_aligned(-3, -3, 0, 0)},
        {"corner on edge", corner_diamond},
    };
    for (const auto& [what, b] : touching) {
        SCOPED_TRACE(what);
        ASSERT_TRUE(convex_quads_meet(a, b));
        expect_verdict_in_every_labelling(a, b, true);
    }
    const std::pair<const char*, rect> one_apart[] = {
        {"edge one unit right", axis_aligned(5, 0, 8, 2)},
        {"edge one unit up", axis_aligned(1, 3, 3, 6)},
        {"corner one unit right", axis_aligned(5, 2, 7, 5)},
        {"corner one unit diagonal", axis_aligned(5, 3, 7, 5)},
        {"corner diamond one unit right", translated(corner_diamond, {1, 0})},
    };
    for (const auto& [what, b] : one_apart) {
        SCOPED_TRACE(what);
        ASSERT_FALSE(convex_quads_meet(a, b));
        expect_verdict_in_every_labelling(a, b, false);
    }
}

TEST(sat4_ref, touching_turned_integer_rectangles_collide_and_one_unit_apart_separate) {
    // Edges u = (3, 4) and v = 2 * (-4, 3): every corner is an integer.
    const point u{3, 4}, w{-4, 3}, v{-8, 6};
    const point origin{5, -2};
    const rect a = from_edges(origin, u, v);
    const point right_low = plus(origin, u);       // A.LR
    const point right_mid = plus(right_low, w);    // on A's right edge
    const point top_right = plus(right_low, v);    // A.UR
    const point diagonal_u = plus(u, w);           // u turned 45 degrees left, outward
    const point diagonal_v{u.x - w.x, u.y - w.y};  // u turned 45 degrees right, outward
    const std::pair<const char*, rect> touching[] = {
        {"edge on full edge", from_edges(right_low, u, v)},
        {"edge on part of an edge", from_edges(right_mid, u, v)},
        {"corner on corner", from_edges(top_right, u, v)},
        {"turned corner on corner", from_edges(top_right, diagonal_u, diagonal_v)},
        {"corner on edge", from_edges(right_mid, diagonal_u, diagonal_v)},
    };
    for (const auto& [what, b] : touching) {
        SCOPED_TRACE(what);
        ASSERT_TRUE(convex_quads_meet(a, b));
        expect_verdict_in_every_labelling(a, b, true);
    }
    // One lattice step outward along +x (which has a positive share of u).
    const point step{1, 0};
    for (const auto& [what, b] : touching) {
        SCOPED_TRACE(std::string(what) + ", one unit right");
        const rect apart = translated(b, step);
        ASSERT_FALSE(convex_quads_meet(a, apart));
        expect_verdict_in_every_labelling(a, apart, false);
    }
}

TEST(sat4_ref, identical_and_nested_rectangles_collide) {
    const rect outer = from_edges({-7, 3}, {6, 8}, {-16, 12});
    const rect inner = from_edges({-5, 7}, {3, 4}, {-4, 3});
    ASSERT_FALSE(any_corner_inside(inner, outer));
    ASSERT_TRUE(convex_quads_meet(outer, inner));
    expect_verdict_in_every_labelling(outer, outer, true);
    expect_verdict_in_every_labelling(outer, inner, true);
    const rect axis_outer = axis_aligned(-5, -5, 5, 5);
    const rect axis_inner = axis_aligned(-1, -2, 3, 4);
    expect_verdict_in_every_labelling(axis_outer, axis_inner, true);
    // A turned rectangle inside an axis-aligned one with a corner on its edge.
    expect_verdict_in_every_labelling(axis_outer, rect{{0, 5}, {5, 0}, {0, -5}, {-5, 0}}, true);
}

TEST(sat4_ref, degenerate_points_and_segments_follow_the_projection_rule) {
    // The method answers for the quadrilateral as given; with zero-size axes
    // every scalar is 0, so only the other rectangle's axes can separate.
    const rect box = axis_aligned(0, 0, 4, 2);
    EXPECT_TRUE(sat4(point_rect({1, 1}), box));
    EXPECT_TRUE(sat4(box, point_rect({4, 2})));  // on the corner
    EXPECT_FALSE(sat4(point_rect({5, 1}), box));
    EXPECT_FALSE(sat4(box, point_rect({5, 1})));
    EXPECT_TRUE(sat4(segment_rect({-1, 1}, {5, 1}), box));   // crossing it
    EXPECT_FALSE(sat4(segment_rect({-1, 3}, {5, 3}), box));  // above it
    // Two points have only zero axes: nothing can separate them.
    EXPECT_TRUE(sat4(point_rect({0, 0}), point_rect({100, -7})));
}

// Integer rectangles small enough that every float operation of the method is
// exact: the verdict must then be the exact geometric one, in every labelling.
TEST(sat4_ref, exact_on_small_integer_rectangles_against_an_independent_oracle) {
    obbsat::seeded_random random(20240611);
    auto small_int = [&](int lo, int hi) {
        return lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
    };
    auto random_integer_rect = [&]() {
        int a = 0, b = 0;
        while (a == 0 && b == 0) {
            a = small_int(-4, 4);
            b = small_int(-4, 4);
        }
        const point origin{static_cast<float>(small_int(-8, 8)),
                           static_cast<float>(small_int(-8, 8))};
        return integer_rect(origin, a, b, small_int(1, 3));
    };
    std::size_t meeting = 0, corner_on_boundary = 0, bounds_only = 0;
    constexpr int pair_count = 200000;
    for (int i = 0; i < pair_count; ++i) {
        const rect a = random_integer_rect();
        const rect b = random_integer_rect();
        const bool truth = convex_quads_meet(a, b);
        ASSERT_EQ(sat4(a, b), truth) << "A " << describe(a) << "\nB " << describe(b);
        ASSERT_EQ(sat4(b, a), truth) << "swapped; A " << describe(a) << "\nB " << describe(b);
        ASSERT_EQ(sat4(reversed_winding(a), relabelled(b)), truth)
            << "relabelled; A " << describe(a) << "\nB " << describe(b);
        meeting += truth ? 1u : 0u;
        bounds_only += (!truth && aabbs_overlap(a, b)) ? 1u : 0u;
        const auto qa = lattice_corners(a);
        for (const auto& p : lattice_corners(b)) {
            for (unsigned k = 0; k < 4; ++k) {
                const lattice_point from = qa[k], to = qa[(k + 1) % 4];
                corner_on_boundary +=
                    (orientation(from, to, p) == 0 && within_box(from, to, p)) ? 1u : 0u;
            }
        }
    }
    // The sweep must exercise every kind of answer, not only the easy ones.
    EXPECT_GT(meeting, static_cast<std::size_t>(pair_count / 20));
    EXPECT_LT(meeting, static_cast<std::size_t>(pair_count - pair_count / 20));
    EXPECT_GT(corner_on_boundary, 1000u) << "corners of B exactly on the boundary of A";
    EXPECT_GT(bounds_only, 1000u) << "separated pairs whose bounds overlap";
}

}  // namespace
