// What a method on doubles (--precision double) saw along its axes, for a
// drawing, with every scalar measured from the pair's own origin so that a
// pair at 1e6 or 1e15 draws as well as one at the origin.
//
// Double poses: the pose test's four axes, A's x and y then B's (as
// svg_pose_axes.hpp). Method local is replayed through its double reference's
// steps (ref::local_axes on rect_pose64), so each axis's verdict is the
// method's; conservative and exact are judged by the double pose oracle's
// exact slack signs (oracle::slack_signs on rect_pose64), their bars drawn from
// local's double offsets and reaches.
//
// Double corners: the edge directions of A and B (UR - UL and LR - UR of each),
// every corner's projection computed in double from corners measured from the
// origin. The verdict drawn is the library's (exact by the double oracle,
// conservative with its margin); an axis whose double projections disagree
// with it gets a note rather than an error, as these scalars are a drawing's,
// not the method's steps.
#pragma once

#include "draw/svg_pair_axes.hpp"
#include "draw/svg_pair_contact.hpp"

#include <obbsat/method.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose64.hpp>

namespace obbsat::svg {

/// The view of method `m` (local, conservative or exact) on double poses (a,
/// b), whose verdict the library gave as `collides`; scalars measured from A's
/// centre. Throws std::logic_error if the replayed steps or the exact signs
/// contradict the verdict, std::invalid_argument for another method.
method_view view_of_pose64_method(method m, const rect_pose64& a, const rect_pose64& b, bool collides);

/// The view of method `m` (conservative or exact) on double corners (a, b),
/// whose verdict the library gave as `collides`; scalars measured from `origin`.
method_view view_of_rect64_method(method m, const rect64& a, const rect64& b, bool collides, world_point origin);

}  // namespace obbsat::svg
