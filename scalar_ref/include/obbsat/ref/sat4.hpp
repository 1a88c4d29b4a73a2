// Method sat4: the separating axis test for two rotated rectangles, exactly as
// the article "2D Rotated Rectangle Collision" describes it, in float32.
//
// This is the specification of the method. Every backend (scalar, SSE2, AVX2,
// AVX-512) must reach the same verdict as `sat4` below for every finite input,
// so the operation order is part of the contract:
//
//   1. Axes, each component one float subtraction:
//        axis1 = A.UR - A.UL     axis2 = A.UR - A.LR
//        axis3 = B.UL - B.LL     axis4 = B.UL - B.UR
//   2. The scalar of corner p on axis a is  (p.x * a.x) + (p.y * a.y):
//        two float multiplications, each rounded, then one float addition,
//        rounded. No fused multiply-add.
//   3. Per rectangle, min and max of its four scalars, folded in corner order
//        UL, UR, LR, LL as  m = pick(pick(pick(s_UL, s_UR), s_LR), s_LL)
//        with  min-pick(u, v) = (u < v) ? u : v  and  max-pick(u, v) = (u > v) ? u : v.
//   4. The axis shows overlap iff  minB <= maxA  and  maxB >= minA
//        (ordered comparisons: false when either side is NaN).
//   5. The rectangles collide iff all four axes show overlap; touching collides.
//      The test stops at the first axis without overlap (this changes no verdict).
//
// The picks in step 3 are written that way on purpose: they are the exact
// semantics of the x86 SIMD min/max instructions, so a scalar that overflowed
// to infinity, or a NaN from infinity minus infinity, gives the same verdict on
// every backend.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref {

/// The interval a rectangle's corners cover on one axis, as dot-product scalars.
struct extent {
    float min;
    float max;
};

/// The axis from `from` to `to`: to - from, per component.
point axis_between(point from, point to);

/// The scalar of `corner` on `axis`: (x * ax) + (y * ay), each operation rounded to float.
float scalar_on_axis(point corner, point axis);

/// The smaller of two scalars as the SIMD min instruction picks it: u < v ? u : v.
float min_pick(float u, float v);

/// The larger of two scalars as the SIMD max instruction picks it: u > v ? u : v.
float max_pick(float u, float v);

/// min and max of the four corner scalars of `r` on `axis`, folded UL, UR, LR, LL.
extent project_rect(const rect& r, point axis);

/// True iff the two extents overlap: b.min <= a.max and b.max >= a.min.
bool extents_overlap(extent a, extent b);

/// The article's four axes for the pair (a, b), in the order they are tested.
void sat4_axes(const rect& a, const rect& b, point axes[4]);

/// Method sat4: true iff no axis separates a and b (touching collides).
bool sat4(const rect& a, const rect& b);

}  // namespace obbsat::ref
