#include "sat4_steps.hpp"

#include <obbsat/ref/sat4_double.hpp>

namespace obbsat::ref {

namespace {

steps::vec2<double> as_vec(double_axis v) { return steps::vec2<double>{v.x, v.y}; }

}  // namespace

void sat4_double_axes(const rect& a, const rect& b, double_axis axes[4]) {
    steps::vec2<double> steps_axes[4];
    steps::article_axes(steps::quad<double>(a), steps::quad<double>(b), steps_axes);
    for (int k = 0; k < 4; ++k) {
        axes[k] = double_axis{steps_axes[k].x, steps_axes[k].y};
    }
}

double_extent sat4_double_projection(const rect& r, double_axis axis) {
    const steps::extent<double> e = steps::project(steps::quad<double>(r), as_vec(axis));
    return double_extent{e.min, e.max};
}

bool double_extents_overlap(double_extent a, double_extent b) {
    return steps::overlap(steps::extent<double>{a.min, a.max}, steps::extent<double>{b.min, b.max});
}

bool sat4_double(const rect& a, const rect& b) {
    return steps::collide(steps::quad<double>(a), steps::quad<double>(b));
}

}  // namespace obbsat::ref
