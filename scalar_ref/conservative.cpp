#include "sat4_steps.hpp"

#include <obbsat/ref/conservative.hpp>

#include <cmath>
#include <initializer_list>

namespace obbsat::ref {

namespace {

float largest_magnitude(const rect& r, float so_far) {
    for (const point p : {r.ul, r.ur, r.lr, r.ll}) {
        so_far = max_pick(so_far, std::fabs(p.x));
        so_far = max_pick(so_far, std::fabs(p.y));
    }
    return so_far;
}

}  // namespace

float conservative_scale(const rect& a, const rect& b) {
    const float k = largest_magnitude(b, largest_magnitude(a, 0.0f));
    const float guarded = k * 0x1p66f;  // exact below 2^62, +inf from there on
    return guarded * 0x1.004p-87f;
}

float fused_scalar_on_axis(point corner, point axis) {
    const float along_y = corner.y * axis.y;
    return std::fma(corner.x, axis.x, along_y);
}

extent project_rect_fused(const rect& r, point axis) {
    const float ul = fused_scalar_on_axis(r.ul, axis);
    const float ur = fused_scalar_on_axis(r.ur, axis);
    const float lr = fused_scalar_on_axis(r.lr, axis);
    const float ll = fused_scalar_on_axis(r.ll, axis);
    const steps::extent<float> e = steps::fold_extent(ul, ur, lr, ll);
    return extent{e.min, e.max};
}

float conservative_margin(point axis, float scale) {
    return std::fma(scale, max_pick(std::fabs(axis.x), std::fabs(axis.y)), 0x1p-140f);
}

bool proven_apart(extent a, extent b, float margin) {
    return max_pick(b.min - a.max, a.min - b.max) > margin;
}

bool conservative(const rect& a, const rect& b) {
    const float scale = conservative_scale(a, b);
    point axes[4];
    sat4_axes(a, b, axes);
    for (const point axis : axes) {
        if (proven_apart(project_rect_fused(a, axis), project_rect_fused(b, axis), conservative_margin(axis, scale))) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref
