// A rectangle as scenes usually store it: center, half extents and angle.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

namespace obbsat {

/// A rectangle by center, half width and half height (along its own x and y),
/// and counter-clockwise rotation in radians.
struct pose {
    point center;
    point half_extents;
    float angle;
};

/// The corners of `p`: UL = c + R(-hx, +hy), UR = c + R(hx, hy),
/// LR = c + R(hx, -hy), LL = c + R(-hx, -hy), computed in double, rounded once.
rect corners_of(const pose& p);

/// A pose that reproduces the corners of `r` to within rounding when `r` is a
/// rectangle: center = mean of the corners, half width = |UR - UL| / 2, half
/// height = |UR - LR| / 2, angle = direction of UR - UL; computed in double.
pose pose_of(const rect& r);

/// The pose of `p` with a rotation vector: (c, s) = (cos(angle), sin(angle))
/// computed in double (std::cos, std::sin) and rounded to float; center and
/// half extents copied. The same bits on every backend (it runs on none).
rect_pose rect_pose_of(const pose& p);

/// A pose for the corners of `r`, in double, each result rounded once:
/// center = mean of the four corners, hx = |UR − UL| / 2, hy = |UR − LR| / 2,
/// rotation = (UR − UL) / |UR − UL|, or where UR = UL the unit vector that
/// turns UR − LR to (0, 1) by −90°, or (1, 0) when all corners coincide.
/// For a true rectangle the pose's set is r's to within rounding; for any
/// other quad it is a rectangle near it, not the quad.
rect_pose rect_pose_of(const rect& r);

}  // namespace obbsat
