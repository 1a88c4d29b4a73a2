// The pose (center, half extents, angle) of a rectangle given by its corners,
// for peers that build their own boxes from a pose. The scenes store corners
// only; this recovers a pose that reproduces them to within float rounding,
// which is all a speed comparison needs (the peers' agreement counter shows
// how far verdicts drift).
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>

#include <cmath>

namespace obbsat_bench {

/// center = mean of the corners, half width = |UR - UL| / 2, half height =
/// |UR - LR| / 2, angle = direction of UR - UL; computed in double.
inline obbsat::pose pose_from_corners(const obbsat::rect& r) {
    const double cx = (static_cast<double>(r.ul.x) + r.ur.x + r.lr.x + r.ll.x) / 4.0;
    const double cy = (static_cast<double>(r.ul.y) + r.ur.y + r.lr.y + r.ll.y) / 4.0;
    const double wx = static_cast<double>(r.ur.x) - r.ul.x;
    const double wy = static_cast<double>(r.ur.y) - r.ul.y;
    const double hx = static_cast<double>(r.ur.x) - r.lr.x;
    const double hy = static_cast<double>(r.ur.y) - r.lr.y;
    obbsat::pose p;
    p.center = obbsat::point{static_cast<float>(cx), static_cast<float>(cy)};
    p.half_extents = obbsat::point{static_cast<float>(std::hypot(wx, wy) / 2.0),
                                   static_cast<float>(std::hypot(hx, hy) / 2.0)};
    p.angle = static_cast<float>(std::atan2(wy, wx));
    return p;
}

}  // namespace obbsat_bench
