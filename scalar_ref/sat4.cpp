#include "sat4_steps.hpp"

#include <obbsat/ref/sat4.hpp>

namespace obbsat::ref {

namespace {

steps::vec2<float> as_vec(point p) { return steps::vec2<float>{p.x, p.y}; }
point as_point(steps::vec2<float> v) { return point{v.x, v.y}; }

}  // namespace

point axis_between(point from, point to) {
    return as_point(steps::axis_between(as_vec(from), as_vec(to)));
}

float scalar_on_axis(point corner, point axis) {
    return steps::scalar_on_axis(as_vec(corner), as_vec(axis));
}

float min_pick(float u, float v) { return steps::min_pick(u, v); }

float max_pick(float u, float v) { return steps::max_pick(u, v); }

extent project_rect(const rect& r, point axis) {
    const steps::extent<float> e = steps::project(steps::quad<float>(r), as_vec(axis));
    return extent{e.min, e.max};
}

bool extents_overlap(extent a, extent b) {
    return steps::overlap(steps::extent<float>{a.min, a.max}, steps::extent<float>{b.min, b.max});
}

void sat4_axes(const rect& a, const rect& b, point axes[4]) {
    steps::vec2<float> steps_axes[4];
    steps::article_axes(steps::quad<float>(a), steps::quad<float>(b), steps_axes);
    for (int k = 0; k < 4; ++k) {
        axes[k] = as_point(steps_axes[k]);
    }
}

bool sat4(const rect& a, const rect& b) {
    return steps::collide(steps::quad<float>(a), steps::quad<float>(b));
}

}  // namespace obbsat::ref
