// The pose (center, half extents, angle) of a rectangle given by its corners,
// for peers that build their own boxes from a pose. The scenes store corners
// only; this recovers a pose that reproduces them to within float rounding,
// which is all a speed comparison needs (the peers' agreement counter shows
// how far verdicts drift).
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>


namespace obbsat_bench {

/// The library's pose_of: center = mean of the corners, half extents from
/// |UR - UL| and |UR - LR|, angle of UR - UL.
inline obbsat::pose pose_from_corners(const obbsat::rect& r) { return obbsat::pose_of(r); }

}  // namespace obbsat_bench
