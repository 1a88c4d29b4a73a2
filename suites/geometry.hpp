// Plane geometry in double for building cases before the single rounding to
// float that makes them hard: vectors, quads (corners UL, UR, LR, LL) and
// rotations from the rational parametrisation of the unit circle.
#pragma once

#include <obbsat/rect.hpp>

#include <array>

namespace obbsat::suites::detail {

struct vec {
    double x;
    double y;
};

inline vec operator+(vec a, vec b) { return vec{a.x + b.x, a.y + b.y}; }
inline vec operator-(vec a, vec b) { return vec{a.x - b.x, a.y - b.y}; }
inline vec operator*(double s, vec a) { return vec{s * a.x, s * a.y}; }
inline double dot(vec a, vec b) { return a.x * b.x + a.y * b.y; }
inline double cross(vec a, vec b) { return a.x * b.y - a.y * b.x; }
/// `a` turned a quarter counter-clockwise.
inline vec perp(vec a) { return vec{-a.y, a.x}; }
/// `v` in the frame whose x axis is the unit vector `axis`.
inline vec rotate(vec v, vec axis) { return vec{axis.x * v.x - axis.y * v.y, axis.y * v.x + axis.x * v.y}; }

/// The unit vector ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)): angle 2 atan(t).
vec unit_from_parameter(double t);

/// `v` scaled to length 1 (sqrt is correctly rounded, so this is portable).
vec normalized(vec v);

/// Corners UL, UR, LR, LL.
using quad = std::array<vec, 4>;

/// The rectangle with this center, x axis (unit) and half extents:
/// UL = c + R(-hw, hh), UR = c + R(hw, hh), LR = c + R(hw, -hh), LL = c + R(-hw, -hh).
quad box(vec center, vec axis, double half_width, double half_height);

/// `q` moved by `offset`.
quad translated(const quad& q, vec offset);

/// Every corner multiplied by `scale`, then moved by `offset`.
quad scaled(const quad& q, double scale, vec offset);

/// Each coordinate rounded to the nearest float, once.
rect to_rect(const quad& q);

/// The float corners as doubles (exact).
quad to_quad(const rect& r);

/// The mean of the corners.
vec centroid(const quad& q);

}  // namespace obbsat::suites::detail
