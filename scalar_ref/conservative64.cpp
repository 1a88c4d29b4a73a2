#include "sat4_steps.hpp"

#include <obbsat/ref/conservative64.hpp>

#include <cmath>
#include <initializer_list>

namespace obbsat::ref {

namespace {

using steps::max_pick;
using steps::min_pick;

double largest_magnitude(const rect64& r, double so_far) {
    for (const point64 p : {r.ul, r.ur, r.lr, r.ll}) {
        so_far = max_pick(so_far, std::fabs(p.x));
        so_far = max_pick(so_far, std::fabs(p.y));
    }
    return so_far;
}

double scale_of(const rect64& a, const rect64& b) {
    const double k = largest_magnitude(b, largest_magnitude(a, 0.0));
    const double guarded = k * 0x1p513;  // exact below 2^511, +inf from there on
    return guarded * 0x1.004p-563;
}

point64 axis_between(point64 from, point64 to) { return point64{to.x - from.x, to.y - from.y}; }

double fused_scalar(point64 corner, point64 axis) { return std::fma(corner.x, axis.x, corner.y * axis.y); }

steps::extent<double> project(const rect64& r, point64 axis) {
    return steps::fold_extent(fused_scalar(r.ul, axis), fused_scalar(r.ur, axis), fused_scalar(r.lr, axis),
                              fused_scalar(r.ll, axis));
}

}  // namespace

bool conservative(const rect64& a, const rect64& b) {
    const double scale = scale_of(a, b);
    const point64 axes[4] = {axis_between(a.ul, a.ur), axis_between(a.lr, a.ur), axis_between(b.ll, b.ul),
                             axis_between(b.ur, b.ul)};
    for (const point64 axis : axes) {
        const steps::extent<double> ea = project(a, axis);
        const steps::extent<double> eb = project(b, axis);
        const double margin = std::fma(scale, max_pick(std::fabs(axis.x), std::fabs(axis.y)), 0x1p-1000);
        if (max_pick(eb.min - ea.max, ea.min - eb.max) > margin) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref
