// One rect placed against another in double, at a signed gap along the
// outward normal, before both are rounded to float: with a zero or float-scale
// gap the rounding alone decides whether the floats are separated, touching
// or overlapping.
#pragma once

#include "geometry.hpp"

#include <obbsat/scene.hpp>

#include <string>

namespace obbsat::suites::detail {

enum class contact_mode {
    corner,  ///< a corner of B on an edge of A
    edge,    ///< an edge of B along an edge of A (parallel before rounding)
    vertex,  ///< a corner of B at a corner of A, approaching along A's diagonal
};

/// "corner", "edge" or "vertex".
const char* contact_mode_name(contact_mode mode);

/// A random mode: corner 45%, edge 35%, vertex 20%.
contact_mode random_contact_mode(seeded_random& random);

/// A signed gap relative to the size of A, and its tag ("gap0", "gap+", "gap-"):
/// zero 40%; within a few float steps (2^-30 .. 2^-20) 40%; visible (2^-12 .. 2^-4) 20%.
struct gap {
    double relative;
    const char* name;
};
gap random_gap(seeded_random& random);

/// A rect of half extents (half_width, half_height) placed against `a` (a convex
/// quad, either winding) by `mode` at `signed_gap` (negative: into a). Its
/// orientation is random, except in edge mode where it follows a's edge. The edge (or
/// corner) of a is `edge` (0: UL-UR, 1: UR-LR, 2: LR-LL, 3: LL-UL), or random if negative.
quad place_against(seeded_random& random, const quad& a, contact_mode mode, double half_width,
                   double half_height, double signed_gap, int edge = -1);

/// The length of a's longest edge: the size a relative gap is taken against.
double size_of(const quad& a);

}  // namespace obbsat::suites::detail
