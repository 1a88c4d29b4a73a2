// Method local: the article's local-space test on poses, in float32.
//
// B's center and axes are taken into A's frame: two of the four axes are A's
// own, where A projects to its center plus or minus its half extent and B to
// its center plus or minus the reach of its rotated half extents; then B's two
// axes, the same way round. The projections of the eight corners collapse to
// one center offset and one reach per axis. Axes are the rotation vectors
// themselves, never normalised (the poses' geometry, obbsat/rect_pose.hpp, is
// scaled by them in the same way, so nothing is lost).
//
// Contract, the exact float32 operations in order, each product, sum and
// difference rounded once, no fused multiply-add. For poses a and b with
// centers (ax, ay), (bx, by), half extents (hxa, hya), (hxb, hyb) and
// rotations (ca, sa), (cb, sb):
//   1. dx = bx − ax, dy = by − ay.
//   2. p = (ca·cb) + (sa·sb), q = (ca·sb) − (sa·cb); P = |p|, Q = |q|
//      (the cosine and sine of B's frame seen from A's, each scaled).
//   3. na = (ca·ca) + (sa·sa), nb = (cb·cb) + (sb·sb).
//   4. Per axis, the center offset w and the reach r:
//        A.x  w = (dx·ca) + (dy·sa)   r = ((hxa·na) + (hxb·P)) + (hyb·Q)
//        A.y  w = (dy·ca) − (dx·sa)   r = ((hya·na) + (hxb·Q)) + (hyb·P)
//        B.x  w = (dx·cb) + (dy·sb)   r = ((hxb·nb) + (hxa·P)) + (hya·Q)
//        B.y  w = (dy·cb) − (dx·sb)   r = ((hyb·nb) + (hxa·Q)) + (hya·P)
//   5. An axis shows overlap iff |w| <= r (touching overlaps). The pair
//      collides iff all four do; the test stops at the first that does not,
//      in the order A.x, A.y, B.x, B.y.
// With exact arithmetic this is the separating axis theorem for the two
// rectangles, exact for any poses; in float it may err either way near
// contact, by a few ulps of |d|·|rotation| + |rotation|²·(half extents).
#pragma once

#include <obbsat/rect_pose.hpp>

namespace obbsat::ref {

/// Steps 1 to 4 for one pair: the center offset and reach on each axis, in
/// the order A.x, A.y, B.x, B.y.
struct pose_axes {
    float offset[4];
    float reach[4];
    float dx, dy;  ///< step 1, reused by the margin of the pose conservative method
};

/// Steps 1 to 4 of the contract above.
pose_axes local_axes(const rect_pose& a, const rect_pose& b);

/// Step 5 for axis k (0 to 3, in the order above): |offset| <= reach.
bool shows_overlap(const pose_axes& axes, int k);

/// Method local: true iff |offset| <= reach on all four axes, as specified above.
bool local(const rect_pose& a, const rect_pose& b);

}  // namespace obbsat::ref
