#include <obbsat/ref/sat4.hpp>

namespace obbsat::ref {

point axis_between(point from, point to) {
    return point{to.x - from.x, to.y - from.y};
}

float scalar_on_axis(point corner, point axis) {
    const float along_x = corner.x * axis.x;
    const float along_y = corner.y * axis.y;
    return along_x + along_y;
}

float min_pick(float u, float v) { return (u < v) ? u : v; }

float max_pick(float u, float v) { return (u > v) ? u : v; }

extent project_rect(const rect& r, point axis) {
    const float ul = scalar_on_axis(r.ul, axis);
    const float ur = scalar_on_axis(r.ur, axis);
    const float lr = scalar_on_axis(r.lr, axis);
    const float ll = scalar_on_axis(r.ll, axis);
    return extent{min_pick(min_pick(min_pick(ul, ur), lr), ll),
                  max_pick(max_pick(max_pick(ul, ur), lr), ll)};
}

bool extents_overlap(extent a, extent b) {
    return b.min <= a.max && b.max >= a.min;
}

void sat4_axes(const rect& a, const rect& b, point axes[4]) {
    axes[0] = axis_between(a.ul, a.ur);  // A.UR - A.UL
    axes[1] = axis_between(a.lr, a.ur);  // A.UR - A.LR
    axes[2] = axis_between(b.ll, b.ul);  // B.UL - B.LL
    axes[3] = axis_between(b.ur, b.ul);  // B.UL - B.UR
}

bool sat4(const rect& a, const rect& b) {
    point axes[4];
    sat4_axes(a, b, axes);
    for (const point& axis : axes) {
        // One axis without overlap separates the rectangles: stop there.
        if (!extents_overlap(project_rect(a, axis), project_rect(b, axis))) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref
