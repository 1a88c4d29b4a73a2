// A rectangle by center, half extents and rotation vector, in double.
//
// The geometry, exactly: with every value taken as stored (double),
//
//   rect_pose64{(cx, cy), (hx, hy), (c, s)} is the closed set
//   { (cx, cy) + a·(c, s) + b·(−s, c) : |a| <= hx, |b| <= hy }.
//
// The same set as obbsat::rect_pose (obbsat/rect_pose.hpp) states for
// float32, with no rounding to float anywhere: the rotation vector is not
// normalised (its length scales the rectangle), zero half extents are allowed
// (a segment or a point), a half extent is never negative and the rotation
// vector is never (0, 0). Every method on rect_pose64 answers for this set.
#pragma once

#include <obbsat/rect64.hpp>

namespace obbsat {

/// A rectangle by center, half extents along its own axes, and rotation
/// vector (c, s), all double: its local x axis points along (c, s), its local
/// y axis along (−s, c).
struct rect_pose64 {
    point64 center;
    point64 half_extents;
    point64 rotation;
};

}  // namespace obbsat
