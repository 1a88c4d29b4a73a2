// A rectangle as scenes usually store it: center, half extents and angle.
#pragma once

#include <obbsat/rect.hpp>

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

}  // namespace obbsat
