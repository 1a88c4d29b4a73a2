// A rectangle as a scene holds it: center, half extents and rotation vector.
//
// The geometry, exactly: with every value taken as stored (float32),
//
//   rect_pose{(cx, cy), (hx, hy), (c, s)} is the closed set
//   { (cx, cy) + a·(c, s) + b·(−s, c) : |a| <= hx, |b| <= hy }.
//
// The rotation vector is not normalised: its length scales the rectangle
// (1 within rounding for a unit rotation), so every stored pose is an exact
// rectangle, never "not quite" one. Zero half extents are allowed (a segment
// or a point); a half extent is never negative, and the rotation vector is
// never (0, 0). This is the question every method on poses answers.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat {

/// A rectangle by center, half extents along its own axes, and rotation
/// vector (c, s): its local x axis points along (c, s), its local y axis
/// along (−s, c). For a rotation by angle t, (c, s) = (cos t, sin t).
struct rect_pose {
    point center;
    point half_extents;
    point rotation;
};

}  // namespace obbsat
