// Method local on double poses: the article's local-space test, the steps of
// obbsat/ref/local.hpp with every value and every operation in double.
//
// Contract, the exact double operations in order, each product, sum and
// difference rounded once to double, no fused multiply-add. For poses a and b
// with centers (ax, ay), (bx, by), half extents (hxa, hya), (hxb, hyb) and
// rotations (ca, sa), (cb, sb):
//   1. dx = bx − ax, dy = by − ay.
//   2. p = (ca·cb) + (sa·sb), q = (ca·sb) − (sa·cb); P = |p|, Q = |q|.
//   3. na = (ca·ca) + (sa·sa), nb = (cb·cb) + (sb·sb).
//   4. Per axis, the center offset w and the reach r:
//        A.x  w = (dx·ca) + (dy·sa)   r = ((hxa·na) + (hxb·P)) + (hyb·Q)
//        A.y  w = (dy·ca) − (dx·sa)   r = ((hya·na) + (hxb·Q)) + (hyb·P)
//        B.x  w = (dx·cb) + (dy·sb)   r = ((hxb·nb) + (hxa·P)) + (hya·Q)
//        B.y  w = (dy·cb) − (dx·sb)   r = ((hyb·nb) + (hxa·Q)) + (hya·P)
//   5. An axis shows overlap iff |w| <= r (touching overlaps). The pair
//      collides iff all four do, tested in the order A.x, A.y, B.x, B.y.
// Exact arithmetic would make this the separating axis theorem for the two
// rectangles of obbsat/rect_pose64.hpp; in double it may err either way near
// contact, by a few double ulps of |d|·|rotation| + |rotation|²·(half extents)
// (at UTM coordinates near 1e6, about 1e-9 m where float32 errs by 0.1 m).
#pragma once

#include <obbsat/rect_pose64.hpp>

namespace obbsat::ref {

/// Steps 1 to 4 for one pair: the center offset and reach on each axis, in
/// the order A.x, A.y, B.x, B.y.
struct pose_axes64 {
    double offset[4];
    double reach[4];
    double dx, dy;  ///< step 1, reused by the margins of pose_conservative64.hpp
};

/// Steps 1 to 4 of the contract above.
pose_axes64 local_axes(const rect_pose64& a, const rect_pose64& b);

/// Step 5 for axis k (0 to 3, in the order above): |offset| <= reach.
bool shows_overlap(const pose_axes64& axes, int k);

/// Method local on double poses: true iff |offset| <= reach on all four axes.
bool local(const rect_pose64& a, const rect_pose64& b);

}  // namespace obbsat::ref
