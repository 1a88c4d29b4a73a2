// The steps of the article's separating axis test, written once over the
// arithmetic type (float for sat4, double for sat4_double). The operation
// order is the one scalar_ref/include/obbsat/ref/sat4.hpp states.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref::steps {

template <class Real>
struct vec2 {
    Real x;
    Real y;
};

template <class Real>
struct extent {
    Real min;
    Real max;
};

/// The four corners UL, UR, LR, LL of `r`, converted exactly to Real.
template <class Real>
struct quad {
    vec2<Real> corner[4];

    explicit quad(const rect& r) {
        const point p[4] = {r.ul, r.ur, r.lr, r.ll};
        for (int k = 0; k < 4; ++k) {
            corner[k] = vec2<Real>{static_cast<Real>(p[k].x), static_cast<Real>(p[k].y)};
        }
    }
};

enum corner_index { UL = 0, UR = 1, LR = 2, LL = 3 };

template <class Real>
vec2<Real> axis_between(vec2<Real> from, vec2<Real> to) {
    return vec2<Real>{to.x - from.x, to.y - from.y};
}

template <class Real>
Real scalar_on_axis(vec2<Real> corner, vec2<Real> axis) {
    const Real along_x = corner.x * axis.x;
    const Real along_y = corner.y * axis.y;
    return along_x + along_y;
}

template <class Real>
Real min_pick(Real u, Real v) {
    return (u < v) ? u : v;
}

template <class Real>
Real max_pick(Real u, Real v) {
    return (u > v) ? u : v;
}

/// min and max of the four corner scalars, folded UL, UR, LR, LL with the picks.
template <class Real>
extent<Real> fold_extent(Real ul, Real ur, Real lr, Real ll) {
    return extent<Real>{min_pick(min_pick(min_pick(ul, ur), lr), ll),
                        max_pick(max_pick(max_pick(ul, ur), lr), ll)};
}

template <class Real>
extent<Real> project(const quad<Real>& q, vec2<Real> axis) {
    return fold_extent(scalar_on_axis(q.corner[UL], axis), scalar_on_axis(q.corner[UR], axis),
                       scalar_on_axis(q.corner[LR], axis), scalar_on_axis(q.corner[LL], axis));
}

template <class Real>
bool overlap(extent<Real> a, extent<Real> b) {
    return b.min <= a.max && b.max >= a.min;
}

/// The article's axes A.UR-A.UL, A.UR-A.LR, B.UL-B.LL, B.UL-B.UR, in the order
/// they are tested.
template <class Real>
void article_axes(const quad<Real>& a, const quad<Real>& b, vec2<Real> axes[4]) {
    axes[0] = axis_between(a.corner[UL], a.corner[UR]);
    axes[1] = axis_between(a.corner[LR], a.corner[UR]);
    axes[2] = axis_between(b.corner[LL], b.corner[UL]);
    axes[3] = axis_between(b.corner[UR], b.corner[UL]);
}

/// The article's test: its four axes in order, stopping at the first one
/// without overlap.
template <class Real>
bool collide(const quad<Real>& a, const quad<Real>& b) {
    vec2<Real> axes[4];
    article_axes(a, b, axes);
    for (const vec2<Real>& axis : axes) {
        if (!overlap(project(a, axis), project(b, axis))) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref::steps
