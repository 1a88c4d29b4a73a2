// What a method on poses saw along the four axes of the pose test, for a
// drawing: A's x and y, B's x and y (each pose's rotation vector (c, s) and
// its turn (−s, c), never normalised), each pose's projection on them as its
// centre plus or minus its reach, and which axis separated.
//
// Scalars are measured from A's centre along the axis vector, so A projects
// to 0 ± A's reach and B to the centre offset ± B's reach (both scaled by the
// axis's length, as the methods compute them).
//
// Method local is replayed through its reference's own steps
// (ref::local_axes, ref::shows_overlap), so in its float arithmetic: each
// axis's verdict and centre offset are the method's. A pose's reach alone is
// local_axes's with the other pose's half extents zero, whose terms then
// vanish exactly unless a product overflowed; the method sums both in one
// expression, so the bars may differ from its reach in the last bit.
// The certified methods (conservative, exact) decide from exact signs, so
// their axes are judged by the pose oracle's exact slack signs and drawn from
// its terms in double (oracle::slack_signs, oracle::terms_of_axes).
#pragma once

#include "draw/svg_pair_axes.hpp"

#include <obbsat/method.hpp>
#include <obbsat/rect_pose.hpp>

namespace obbsat::svg {

/// The view of method `m`, one that runs on poses, on the pair (a, b), whose
/// verdict the library gave as `collides`; scalars measured from A's centre,
/// which is the origin of the axes (0, 0). Throws std::logic_error if the
/// replayed steps contradict the verdict, std::invalid_argument for a method
/// that does not run on poses.
method_view view_of_pose_method(method m, const rect_pose& a, const rect_pose& b, bool collides);

}  // namespace obbsat::svg
