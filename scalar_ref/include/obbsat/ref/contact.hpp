// Contacts of two boxes in float32: the specification every backend's lanes
// reproduce bit for bit. In the manner of Box2D 2.4's b2CollidePolygons: find
// the face of largest separation on each box, take the reference face from A
// unless B's is clearly better, take the incident edge of the other box, clip
// it to the reference face's side planes, keep the points not too far apart.
//
// A box is four vertices v[0..3] (UL, UR, LR, LL) and four outward face
// normals n[0..3], face k running from v[k] to v[(k + 1) mod 4]. Normals are
// not unit: every distance taken along one is scaled by the reciprocal of its
// length, inv[k] (one division per face, then products: in lanes a division
// costs as much as several products).
// Vertices are relative to an origin o (A's center for poses, A's UL corner
// for corners), so that two nearby boxes far from (0, 0) lose nothing when
// subtracted; positions are given back as o + p.
//
//   Poses (obbsat/rect_pose.hpp), o = A's center; per box, with
//   (ox, oy) = (cx − o.x, cy − o.y), (ux, uy) = (hx·c, hx·s),
//   (wx, wy) = (hy·s, hy·c):
//     UL = ((ox − ux) − wx, (oy − uy) + wy)   UR = ((ox + ux) − wx, (oy + uy) + wy)
//     LR = ((ox + ux) + wx, (oy + uy) − wy)   LL = ((ox − ux) + wx, (oy − uy) − wy)
//     n = (−s, c), (c, s), (s, −c), (−c, −s)   (exact: only signs change)
//   Corners (obbsat/rect.hpp), o = A's UL: v[k] = (corner k − o), each
//   coordinate one subtraction; edges e[k] = corner (k + 1) − corner k on the
//   corners as given; n[k] = (−e[k].y, e[k].x) when the quad turns clockwise
//   (cross(e[0], e[1]) < 0), (e[k].y, −e[k].x) when it turns counter-clockwise,
//   with cross(p, q) = (p.x·q.y) − (p.y·q.x). The quad must be strictly convex
//   (corners_accepted below); the entry points reject any other.
//
// Then, with dot(p, q) = (p.x·q.x) + (p.y·q.y), every product, sum, quotient
// and square root one IEEE float32 operation in the order written, no fused
// multiply-add; min picks u < v ? u : v and max picks u > v ? u : v, folded
// left over indices 0 to 3; ties go to the lowest index:
//   1. inv[k] = 1 / sqrt(dot(n[k], n[k])) for every face of both boxes (a
//      pose's four faces all get the same value: only signs differ).
//   2. Separation of A's face k:
//        sepA[k] = (min over j of dot(n[k], B.v[j] − A.v[k])) · inv[k],
//      each difference B.v[j] − A.v[k] taken per coordinate; sepB[k] the same
//      with A and B swapped. ia = argmax sepA, sA = sepA[ia]; ib, sB likewise
//      (argmax: the first index holding the maximum, by strict >).
//   3. Span of a box: max(maxx − minx, maxy − miny) over its vertices, each
//      min and max folded over v[0..3]. tol = 2^−10 · min(spanA, spanB).
//      flip = sB > (sA + tol): B's face is the reference only when it
//      separates more than A's by more than tol (A is preferred, so the face
//      does not flicker between steps of a resting contact).
//   4. Reference box R, face r, separation sr: (A, ia, sA), or (B, ib, sB) when
//      flip; incident box I the other. u = (n[r].x · inv[r], n[r].y · inv[r]).
//      normal = u, or (−u.x, −u.y) when flip; depth = 0 − sr.
//   5. Incident face: k minimising dot(I.n[k], u) · I.inv[k] (the first such,
//      by strict <); its edge p1 = I.v[k], p2 = I.v[(k + 1) mod 4].
//   6. Side planes: q1 = R.v[r], q2 = R.v[(r + 1) mod 4], t = q2 − q1,
//      T = dot(t, t), τi = dot(pi − q1, t). The edge is clipped to 0 <= τ <= T
//      (when T is 0, the reference face is one point and nothing is clipped:
//      τ is 0 everywhere). The edge reaches the face unless τ1 < 0 and
//      τ2 < 0, or τ1 > T and τ2 > T (tested as: τ1 >= 0 or τ2 >= 0, and
//      τ1 <= T or τ2 <= T). Then, with g = 1 / (τ1 − τ2), λ0 = τ1 · g and
//      λT = (τ1 − T) · g: an endpoint with τ < 0 moves to λ0, one with τ > T to λT, where the
//      point at λ is (p1.x + (λ·(p2.x − p1.x)), p1.y + (λ·(p2.y − p1.y))).
//   7. Separation of each point: dot(p − q1, u). A point is kept iff
//      sA <= margin, sB <= margin, the edge reaches the face, and its
//      separation <= margin or, when sr <= 0 (touching or overlapping), it is
//      <= the other point's (so such a pair always has a point: a separation
//      of 0 exactly rounds to a few u·R either side, and at margin 0 both
//      could be dropped), and, for p2, unless p1 was kept at the same
//      place (x == x and y == y: a reference face or incident edge of zero
//      length gives one point, not the same twice). Kept points fill points[]
//      in the order p1, p2; point_count is how many; a point's position is
//      (o.x + p.x, o.y + p.y), its separation min(separation, margin) as
//      "separation <= margin ? separation : margin".
//   8. Features of a point (then swapped to A's and B's when flip): an endpoint
//      left in place is (face r of R, vertex of I it is); one moved to λ0 is
//      (vertex r of R, face k of I), to λT (vertex (r + 1) mod 4 of R, face k of I).
//
// Poses take steps 1 to 3 from method local's axes instead (cheaper, and the
// same in exact arithmetic): with a and b the poses,
//   P1. lenA = sqrt(dot(rotA, rotA)), invA = 1 / lenA; the same for B; inv[k]
//       of every face of a box is its inv (the value step 1 gives too).
//   P2. The offsets w and reaches r of obbsat/ref/local.hpp's steps 1 to 4, in
//       its axis order A.x, A.y, B.x, B.y; sep = (|w| − r) · invA on A's axes,
//       · invB on B's. A's axis is A.y iff sep(A.y) > sep(A.x), sA its sep;
//       B's likewise, sB.
//   P3. tol = 2^−10 · min((hxA + hyA) · lenA, (hxB + hyB) · lenB);
//       flip = sB > (sA + tol). The reference face is the face of the chosen
//       axis that faces the other box: on A, A.x gives face 1 when w >= 0,
//       else 3; A.y face 0 when w >= 0, else 2. On B (flip), B.x gives face 3
//       when w >= 0, else 1; B.y face 2 when w >= 0, else 0. That face is
//       step 4's r.
//   Then steps 4 to 8 as above, on the boxes of the pose rule.
//
// With exact arithmetic, for two overlapping rectangles, depth is the
// smallest overlap over the four separating axes (up to tol when A's face is
// kept), the normal its axis, and the points those of Box2D's manifold. In
// float32 every value is within a few ulps of the pair's scale (its distance
// from the origin o plus its sizes) of that.
//
// Double boxes (rect_pose64, rect64; the overloads taking them below): the
// same steps in the same order, every product, sum, quotient and square root
// one IEEE binary64 operation (the square roots and divisions of steps 1, 6
// and P1 in double too), the constants 2^−10 and 0 the same, and "a normal
// float" read as "a normal double" (about 1e-154 to 1e154 long for a
// rotation, c·c + s·s at least 2^−1022). P2 uses obbsat/ref/local64.hpp's
// offsets and reaches. Every value is then within a few double ulps of the
// pair's scale; nothing is computed in float32 and nothing rounded to it.
#pragma once

#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

namespace obbsat::ref {

/// A box as the contact steps see it: vertices relative to an origin and
/// outward face normals (see above).
struct contact_box {
    point v[4];
    point n[4];
};

/// The box of pose `p` relative to `origin` (the header's pose rule).
contact_box contact_box_of(const rect_pose& p, point origin);

/// The box of the corners `r` relative to `origin` (the header's corner rule);
/// `r` is strictly convex (corners_accepted).
contact_box contact_box_of(const rect& r, point origin);

/// Whether the contact of two boxes is defined for corners `r`: the four
/// turns cross(e[k], e[(k + 1) mod 4]) all > 0 or all < 0 (a strictly convex
/// quad, in either winding; a self-intersecting, degenerate or non-convex quad
/// fails), and every edge's dot(e, e) a normal finite float (no edge of zero
/// or overflowing length).
bool corners_accepted(const rect& r);

/// Whether the contact is defined for pose `p`: c·c + s·s a normal finite
/// float (a rotation vector neither below about 1e-19 nor above about 1e19 long).
bool pose_accepted(const rect_pose& p);

/// Steps 1 to 8 for boxes a and b relative to `origin`, keeping points up to
/// `margin` (>= 0): the contact of corner quads.
contact contact_of_boxes(const contact_box& a, const contact_box& b, point origin, float margin);

/// The contact of poses a and b (pose_accepted both): steps P1 to P3, then 4 to 8.
contact contact_of(const rect_pose& a, const rect_pose& b, float margin = 0.0f);

/// The contact of corner quads a and b (corners_accepted both), as specified above.
contact contact_of(const rect& a, const rect& b, float margin = 0.0f);

/// A double box as the contact steps see it (as contact_box, in double).
struct contact_box64 {
    point64 v[4];
    point64 n[4];
};

/// The box of double pose `p` relative to `origin` (the pose rule in double).
contact_box64 contact_box_of(const rect_pose64& p, point64 origin);

/// The box of the double corners `r` relative to `origin`; `r` is strictly
/// convex (corners_accepted).
contact_box64 contact_box_of(const rect64& r, point64 origin);

/// corners_accepted in double: the four turns all > 0 or all < 0, every
/// edge's dot(e, e) a normal finite double.
bool corners_accepted(const rect64& r);

/// pose_accepted in double: c·c + s·s a normal finite double.
bool pose_accepted(const rect_pose64& p);

/// Steps 1 to 8 in double for boxes a and b relative to `origin`.
contact64 contact_of_boxes(const contact_box64& a, const contact_box64& b, point64 origin, double margin);

/// The contact of double poses a and b (pose_accepted both), in double.
contact64 contact_of(const rect_pose64& a, const rect_pose64& b, double margin = 0.0);

/// The contact of double corner quads a and b (corners_accepted both), in double.
contact64 contact_of(const rect64& a, const rect64& b, double margin = 0.0);

}  // namespace obbsat::ref
