// Float bounds that contain a double rectangle's exact point set: what the
// scene queries (obbsat/find_pairs.hpp) compare for double rows. The
// broadphase stays in float32; each double rectangle gets float bounds no
// smaller than its exact set, so two rectangles that share a point have
// overlapping float bounds and the double method sees every such pair.
//
// Contract, in two stages (u = 2^-53, the unit roundoff of double):
//
//   Stage 1, double bounds that contain the exact set.
//     Corners (rect64): the least and greatest x and y of the four corners.
//     No arithmetic: the exact bounds of the quad.
//     Poses (rect_pose64 {(cx, cy), (hx, hy), (c, s)}), per axis, in double:
//       1. ex = (|c|·hx) + (|s|·hy),  ey = (|s|·hx) + (|c|·hy)
//       2. mx = ((|cx| + ex)·2^-50) + 2^-1060,  my likewise with cy, ey
//       3. lo_x = (cx − ex) − mx,  hi_x = (cx + ex) + mx,  lo_y, hi_y likewise.
//     Why they contain the pose (the proof of obbsat/ref/bounds.hpp with
//     u = 2^-53): the exact set spans cx ± ex* along x, ex* = |c|·hx + |s|·hy.
//     Step 1 rounds each product (by at most u relative, or 2^-1075 below
//     the normal range) and the sum once, so |ex − ex*| <= 2.0001u·ex* +
//     2^-1073; cx ∓ ex rounds once more, by at most u·(|cx| + ex). The
//     computed cx ∓ ex is therefore within 3.01u·(|cx| + ex) + 2^-1072 of
//     the exact cx ∓ ex*, while mx >= 7.99u·(|cx| + ex) + 2^-1061 (its
//     three roundings lose less than 0.01u of it and 2^-1075): step 3's
//     difference lies at least 4.98u·(|cx| + ex) beyond the exact bound, more
//     than its own rounding (at most 1.0001u·(|cx| + ex); a difference in the
//     subnormal range is exact). When |cx| + ex overflows, mx is +inf and the
//     bounds are −inf and +inf: containing, never NaN.
//
//   Stage 2, each double bound rounded OUTWARD to float: lo to the greatest
//     float <= it, hi to the least float >= it. A conversion rounds to the
//     nearest float; when that float lies on the wrong side (above a lo,
//     below a hi) the next float towards −inf (+inf) is taken, which is on
//     the right side, as the nearest float and its neighbour bracket the
//     double. A lo beyond FLT_MAX becomes FLT_MAX, a hi below −FLT_MAX
//     becomes −FLT_MAX, an infinite bound stays infinite.
//
// So float lo <= exact lo and float hi >= exact hi, for every valid double
// rectangle, and the bounds are never NaN. (Rounding to nearest, being monotone, would
// already keep every overlap of the double bounds; rounding outward also
// makes the float bounds themselves contain the rectangle, which
// obbsat.bounds in Python and the tests rely on.)
#pragma once

#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/ref/bounds.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace obbsat::ref {

/// The float next to `f` (not NaN) towards +inf (up) or -inf (down), as
/// std::nextafter gives it, by one step of the bit pattern; inline, since
/// the scene queries take four of these per rectangle.
inline float float_step(float f, bool up) {
    if (f == 0.0f) {
        return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
    }
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    // Away from zero is one more in the magnitude's bits, whatever the sign.
    bits = (f > 0.0f) == up ? bits + 1 : bits - 1;
    std::memcpy(&f, &bits, sizeof bits);
    return f;
}

/// The greatest float <= d (d not NaN).
inline float float_at_most(double d) {
    const float f = static_cast<float>(d);
    return static_cast<double>(f) > d ? float_step(f, false) : f;
}

/// The least float >= d (d not NaN).
inline float float_at_least(double d) {
    const float f = static_cast<float>(d);
    return static_cast<double>(f) < d ? float_step(f, true) : f;
}

/// Stage 2 of the contract: double bounds rounded outward to float.
inline box_bounds outward_float_bounds(double lo_x, double lo_y, double hi_x, double hi_y) {
    return box_bounds{float_at_most(lo_x), float_at_most(lo_y), float_at_least(hi_x), float_at_least(hi_y)};
}

/// Float bounds that contain the quad `r` (stage 1 for corners, then stage 2).
inline box_bounds bounds_of(const rect64& r) {
    return outward_float_bounds(std::min(std::min(r.ul.x, r.ur.x), std::min(r.lr.x, r.ll.x)),
                                std::min(std::min(r.ul.y, r.ur.y), std::min(r.lr.y, r.ll.y)),
                                std::max(std::max(r.ul.x, r.ur.x), std::max(r.lr.x, r.ll.x)),
                                std::max(std::max(r.ul.y, r.ur.y), std::max(r.lr.y, r.ll.y)));
}

/// Float bounds that contain the exact point set of `p` (stage 1 for poses, then stage 2).
inline box_bounds bounds_of(const rect_pose64& p) {
    const double ac = std::fabs(p.rotation.x);
    const double as = std::fabs(p.rotation.y);
    const double hx = p.half_extents.x;
    const double hy = p.half_extents.y;
    // Step 1: the half widths of the exact set along x and y.
    const double ex = (ac * hx) + (as * hy);
    const double ey = (as * hx) + (ac * hy);
    // Step 2: the margins covering the rounding of steps 1 and 3.
    const double mx = ((std::fabs(p.center.x) + ex) * 0x1p-50) + 0x1p-1060;
    const double my = ((std::fabs(p.center.y) + ey) * 0x1p-50) + 0x1p-1060;
    // Step 3, then stage 2.
    return outward_float_bounds((p.center.x - ex) - mx, (p.center.y - ey) - my, (p.center.x + ex) + mx,
                                (p.center.y + ey) + my);
}

}  // namespace obbsat::ref
