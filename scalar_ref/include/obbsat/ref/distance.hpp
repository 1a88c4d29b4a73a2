// The distance between two separated boxes and a closest point on each, in
// float32: the specification every backend's lanes reproduce bit for bit.
//
// The boxes are those of the contact reference (obbsat/ref/contact.hpp):
// vertices v[0..3] relative to the origin o (A's center for poses, A's UL
// corner for corners, strictly convex quads only), edges v[k] to v[(k+1) mod 4].
// Every operation is one IEEE float32 operation in the order written, no fused
// multiply-add; dot(p, q) = (p.x·q.x) + (p.y·q.y).
//
//   D1. Whether the pair collides: for poses, method local's verdict
//       (obbsat/ref/local.hpp); for corners, whether on every face k of both
//       boxes min over j of dot(n[k], other.v[j] − v[k]) <= 0 (the contact
//       steps' separations before they are scaled). A colliding pair gets all
//       fields +0, and steps D2 and D3 are skipped.
//   D2. For each edge k of A in order 0 to 3 and, inside, each vertex j of B
//       in order 0 to 3: e = v[k+1] − v[k], ee = dot(e, e), w = B.v[j] − A.v[k];
//       t = dot(w, e) · (1 / ee) when ee > 0, else 0; t = t > 0 ? t : 0, then
//       t < 1 ? t : 1; q = (A.v[k].x + (t·e.x), A.v[k].y + (t·e.y)); the
//       candidate's square d2 = (dx·dx) + (dy·dy) with (dx, dy) = B.v[j] − q, its
//       point of A q and its point of B B.v[j]. Then the same for each edge of
//       B and vertex of A (point of A the vertex, point of B the q on B's edge).
//       The candidate of least d2, the first by strict <, wins.
//   D3. distance = sqrt(d2); the points (o.x + p.x, o.y + p.y).
//
// For two disjoint convex polygons the least distance joins a vertex of one to
// the boundary of the other, so with exact arithmetic this is the distance of
// the closed boxes and a pair of points attaining it; in float32 every value is
// within a few ulps of the pair's scale (its distance from o plus its sizes).
//
// Double boxes (the rect_pose64 and rect64 overloads): the same steps in the
// same order, every operation one IEEE binary64 operation (the division of D2
// and the square root of D3 in double too), D1 for poses by
// obbsat/ref/local64.hpp's verdict; the values then within a few double ulps
// of the pair's scale, nothing rounded to float32.
#pragma once

#include <obbsat/closest_points.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

namespace obbsat::ref {

/// The distance of poses a and b and a closest point on each (ref::pose_accepted both).
closest_points distance_of(const rect_pose& a, const rect_pose& b);

/// The distance of corner quads a and b and a closest point on each (ref::corners_accepted both).
closest_points distance_of(const rect& a, const rect& b);

/// The distance of double poses a and b and a closest point on each, in double.
closest_points64 distance_of(const rect_pose64& a, const rect_pose64& b);

/// The distance of double corner quads a and b and a closest point on each, in double.
closest_points64 distance_of(const rect64& a, const rect64& b);

}  // namespace obbsat::ref
