// Axis-aligned bounds that contain a rectangle's exact point set: what the
// scene queries (obbsat/find_pairs.hpp) compare before any method runs. A
// pair whose bounds do not overlap is never handed to a method.
//
// Contract, the exact float32 operations in order (u = 2^-24):
//
//   Corners (rect): lo_x = the least of the four corners' x, hi_x the
//   greatest, the same for y. No arithmetic, so these are the exact bounds of
//   the quad.
//
//   Poses (rect_pose {(cx, cy), (hx, hy), (c, s)}), per axis:
//     1. ex = (|c|·hx) + (|s|·hy),  ey = (|s|·hx) + (|c|·hy)
//     2. mx = ((|cx| + ex)·2^-21) + 2^-140,  my likewise with cy, ey
//     3. lo_x = (cx − ex) − mx,  hi_x = (cx + ex) + mx,  lo_y, hi_y likewise.
//
// Why the pose bounds contain the pose: the exact set's extent along x is
// cx ± ex* with ex* = |c|·hx + |s|·hy (x = cx + a·c − b·s over |a| <= hx,
// |b| <= hy). Step 1 rounds twice, so |ex − ex*| <= 2.0001u·ex* + 2^-149
// (a product below the normal range errs by at most 2^-150 more); cx ∓ ex
// rounds once more, by at most u·(|cx| + ex). The computed center of each
// bound is therefore within 3.01u·(|cx| + ex) + 2^-149 of the exact one,
// and mx >= 7.99u·(|cx| + ex) + 2^-140·(1 − u) exceeds that with room for
// step 3's last rounding (at most u·(|cx| + ex) + ...). When |cx| + ex
// overflows, mx is +inf and the bounds are (−inf, +inf): still containing,
// never NaN (cx − ex <= cx and cx + ex >= cx are never −inf/+inf the wrong way).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <algorithm>
#include <cmath>

namespace obbsat::ref {

/// Closed axis-aligned bounds [lo_x, hi_x] x [lo_y, hi_y].
struct box_bounds {
    float lo_x;
    float lo_y;
    float hi_x;
    float hi_y;
};

// Both are defined here, inline, so that the scene queries' loops over
// millions of rectangles compile them into their own vector code; the
// operations are the contract's, in its order, wherever they are inlined.

/// The exact bounds of the quad `r` (its corners' least and greatest x and y).
inline box_bounds bounds_of(const rect& r) {
    return box_bounds{std::min(std::min(r.ul.x, r.ur.x), std::min(r.lr.x, r.ll.x)),
                      std::min(std::min(r.ul.y, r.ur.y), std::min(r.lr.y, r.ll.y)),
                      std::max(std::max(r.ul.x, r.ur.x), std::max(r.lr.x, r.ll.x)),
                      std::max(std::max(r.ul.y, r.ur.y), std::max(r.lr.y, r.ll.y))};
}

/// Bounds that contain the exact point set of `p`, by the steps above.
inline box_bounds bounds_of(const rect_pose& p) {
    const float ac = std::fabs(p.rotation.x);
    const float as = std::fabs(p.rotation.y);
    const float hx = p.half_extents.x;
    const float hy = p.half_extents.y;
    // Step 1: the half widths of the exact set along x and y.
    const float ex = (ac * hx) + (as * hy);
    const float ey = (as * hx) + (ac * hy);
    // Step 2: the margins covering the rounding of steps 1 and 3.
    const float mx = ((std::fabs(p.center.x) + ex) * 0x1p-21f) + 0x1p-140f;
    const float my = ((std::fabs(p.center.y) + ey) * 0x1p-21f) + 0x1p-140f;
    // Step 3.
    return box_bounds{(p.center.x - ex) - mx, (p.center.y - ey) - my, (p.center.x + ex) + mx,
                      (p.center.y + ey) + my};
}

/// True iff the closed bounds share a point (touching bounds overlap).
inline bool bounds_overlap(const box_bounds& a, const box_bounds& b) {
    return a.lo_x <= b.hi_x && b.lo_x <= a.hi_x && a.lo_y <= b.hi_y && b.lo_y <= a.hi_y;
}

}  // namespace obbsat::ref
