// The corners of a pose, in float32: the conversion the SIMD backends
// reproduce bit for bit (rect_records::from(pose_records)). For users who keep
// the corner methods and hold poses.
//
// With u = (hx·c, hx·s) (half of the local x side) and v = (−w, hy·c),
// w = hy·s (half of the local y side), each product rounded once:
//   UL = ((cx − ux) − w, (cy − uy) + vy)    UR = ((cx + ux) − w, (cy + uy) + vy)
//   LR = ((cx + ux) + w, (cy + uy) − vy)    LL = ((cx − ux) + w, (cy − uy) − vy)
// every sum and difference rounded once, in the order the parentheses give;
// no fused multiply-add and no negation (so no backend's way of negating a
// zero can change a sign). The corners are the pose's rectangle to within a few
// ulps of |center| + |u| + |v|; a corner method on them answers for the
// rounded quad, not for the pose (use the pose methods for that).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

namespace obbsat::ref {

/// The corners of `p` in the order UL, UR, LR, LL, as stated above.
rect corners_of(const rect_pose& p);

}  // namespace obbsat::ref
