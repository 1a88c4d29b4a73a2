// How close a pair sits to the boundary between contact classes, measured in
// float steps, with the exact oracle (of quads, or of poses).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

namespace obbsat::suites {

/// `r` with every x coordinate moved `steps_x` floats (towards +infinity if positive,
/// -infinity if negative) and every y coordinate `steps_y` floats.
rect nudge(const rect& r, int steps_x, int steps_y);

/// True iff a and b touch, or moving b by 1..`steps` floats along +x, -x, +y or -y
/// changes their contact class.
bool near_contact_boundary(const rect& a, const rect& b, unsigned steps);

/// `p` with its center moved `steps_x` floats in x and `steps_y` in y (signs as for rects).
rect_pose nudge(const rect_pose& p, int steps_x, int steps_y);

/// True iff the poses a and b touch, or moving b's center by 1..`steps` floats along
/// +x, -x, +y or -y changes their contact class.
bool near_contact_boundary(const rect_pose& a, const rect_pose& b, unsigned steps);

}  // namespace obbsat::suites
