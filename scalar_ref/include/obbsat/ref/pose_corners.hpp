// The corners of a pose, in float32: the conversion the SIMD backends
// reproduce bit for bit (rect_records::from(pose_records)). For users who keep
// the corner methods and hold poses.
//
// With u = (hx·c, hx·s) (half of the local x side) and v = (−(hy·s), hy·c)
// (half of the local y side), each product rounded once:
//   UL = ((cx − ux) + vx, (cy − uy) + vy)    UR = ((cx + ux) + vx, (cy + uy) + vy)
//   LR = ((cx + ux) − vx, (cy + uy) − vy)    LL = ((cx − ux) − vx, (cy − uy) − vy)
// every sum and difference rounded once, in the order the parentheses give;
// no fused multiply-add. The corners are the pose's rectangle to within a few
// ulps of |center| + |u| + |v|; a corner method on them answers for the
// rounded quad, not for the pose (use the pose methods for that).
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

namespace obbsat::ref {

/// The corners of `p` in the order UL, UR, LR, LL, as stated above.
rect corners_of(const rect_pose& p);

}  // namespace obbsat::ref
