#include <obbsat/ref/bounds.hpp>

#include <algorithm>
#include <cmath>

namespace obbsat::ref {

box_bounds bounds_of(const rect& r) {
    return box_bounds{std::min(std::min(r.ul.x, r.ur.x), std::min(r.lr.x, r.ll.x)),
                      std::min(std::min(r.ul.y, r.ur.y), std::min(r.lr.y, r.ll.y)),
                      std::max(std::max(r.ul.x, r.ur.x), std::max(r.lr.x, r.ll.x)),
                      std::max(std::max(r.ul.y, r.ur.y), std::max(r.lr.y, r.ll.y))};
}

box_bounds bounds_of(const rect_pose& p) {
    const float ac = std::fabs(p.rotation.x);
    const float as = std::fabs(p.rotation.y);
    const float hx = p.half_extents.x;
    const float hy = p.half_extents.y;
    // Step 1: the half widths of the exact set along x and y.
    const float ex = (ac * hx) + (as * hy);
    const float ey = (as * hx) + (ac * hy);
    // Step 2: the margins covering the rounding of steps 1 and 3.
    const float mx = ((std::fabs(p.center.x) + ex) * 0x1p-21f) + 0x1p-140f;
    const float my = ((std::fabs(p.center.y) + ey) * 0x1p-21f) + 0x1p-140f;
    // Step 3.
    return box_bounds{(p.center.x - ex) - mx, (p.center.y - ey) - my, (p.center.x + ex) + mx,
                      (p.center.y + ey) + my};
}

}  // namespace obbsat::ref
