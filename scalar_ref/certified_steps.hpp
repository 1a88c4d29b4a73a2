// The steps of the certified separating-edge test (obbsat/ref/certified.hpp),
// written once over the corner type: obbsat::rect with float arithmetic, and
// obbsat::rect64 with double arithmetic (obbsat/ref/certified64.hpp). Only the
// guard's range and the bound's factor differ, and they are the caller's.
#pragma once

#include <obbsat/ref/certified.hpp>

#include <initializer_list>

namespace obbsat::ref::certified_steps {

/// The guard and the bound of one precision: decide nothing unless
/// min_area <= area <= max_area (pair) and min_area <= own area (each quad);
/// bound = area · bound_factor.
template <class Real>
struct limits {
    Real min_area;
    Real max_area;
    Real bound_factor;
};

template <class Real>
Real min_pick(Real u, Real v) {
    return (u < v) ? u : v;
}

template <class Real>
Real max_pick(Real u, Real v) {
    return (u > v) ? u : v;
}

template <class Point>
struct quad_edges {
    using Real = decltype(Point::x);
    Point corner[4];
    Point edge[4];  // corner[k+1] - corner[k]
    Real winding;   // +1 counter-clockwise, -1 clockwise, 0 not proven convex
};

template <class Point, class Quad>
quad_edges<Point> edges_of(const Quad& r, decltype(Point::x) own_bound) {
    using Real = decltype(Point::x);
    quad_edges<Point> q{{r.ul, r.ur, r.lr, r.ll}, {}, Real(0)};
    for (int k = 0; k < 4; ++k) {
        const Point& from = q.corner[k];
        const Point& to = q.corner[(k + 1) % 4];
        q.edge[k] = Point{to.x - from.x, to.y - from.y};
    }
    bool all_left = true;
    bool all_right = true;
    for (int k = 0; k < 4; ++k) {
        const Point& e = q.edge[k];
        const Point& next = q.edge[(k + 1) % 4];
        const Real turn = (e.x * next.y) - (e.y * next.x);
        all_left = all_left && turn > own_bound;
        all_right = all_right && turn < -own_bound;
    }
    q.winding = all_left ? Real(1) : (all_right ? Real(-1) : Real(0));
    return q;
}

// The orientation of r against edge k of q, sign-flipped for clockwise q so
// that negative always means outside.
template <class Point>
decltype(Point::x) outward_orientation(const quad_edges<Point>& q, int k, Point r) {
    const Point& p = q.corner[k];
    const Point& e = q.edge[k];
    const decltype(Point::x) d = (e.x * (r.y - p.y)) - (e.y * (r.x - p.x));
    return q.winding < 0 ? -d : d;
}

// Over the edges of `q` against the corners of `other`: some edge with every
// corner outside (separating), and every edge with some corner inside (blocked).
template <class Point>
void scan_edges(const quad_edges<Point>& q, const quad_edges<Point>& other, decltype(Point::x) bound,
                bool& separating, bool& all_blocked) {
    for (int k = 0; k < 4; ++k) {
        bool all_outside = true;
        bool any_inside = false;
        for (const Point& r : other.corner) {
            const auto sd = outward_orientation(q, k, r);
            all_outside = all_outside && sd < -bound;
            any_inside = any_inside || sd > bound;
        }
        separating = separating || all_outside;
        all_blocked = all_blocked && any_inside;
    }
}

template <class Real>
struct extent {
    Real xmin, xmax, ymin, ymax;

    Real area() const { return (xmax - xmin) * (ymax - ymin); }
};

template <class Real, class Quad>
extent<Real> extent_of(const Quad& r) {
    extent<Real> e{r.ul.x, r.ul.x, r.ul.y, r.ul.y};
    for (const auto& p : {r.ur, r.lr, r.ll}) {
        e.xmin = min_pick(e.xmin, p.x);
        e.xmax = max_pick(e.xmax, p.x);
        e.ymin = min_pick(e.ymin, p.y);
        e.ymax = max_pick(e.ymax, p.y);
    }
    return e;
}

template <class Real>
extent<Real> joined(const extent<Real>& a, const extent<Real>& b) {
    return extent<Real>{min_pick(a.xmin, b.xmin), max_pick(a.xmax, b.xmax), min_pick(a.ymin, b.ymin),
                        max_pick(a.ymax, b.ymax)};
}

/// The whole test: steps 1 to 7 of obbsat/ref/certified.hpp for corners of type
/// Quad (with points of type Point), in Point's arithmetic.
template <class Point, class Quad>
certified_verdict certify(const Quad& a, const Quad& b, const limits<decltype(Point::x)>& limit) {
    using Real = decltype(Point::x);
    const extent<Real> ea = extent_of<Real>(a);
    const extent<Real> eb = extent_of<Real>(b);
    const Real area_a = ea.area();
    const Real area_b = eb.area();
    const Real area = joined(ea, eb).area();
    // NaN (from an infinite width) fails every comparison: out of range.
    const bool in_range = area >= limit.min_area && area <= limit.max_area;
    if (!(in_range && area_a >= limit.min_area && area_b >= limit.min_area)) {
        return certified_verdict{false, false};
    }
    const Real bound = area * limit.bound_factor;
    const quad_edges<Point> qa = edges_of<Point>(a, area_a * limit.bound_factor);
    const quad_edges<Point> qb = edges_of<Point>(b, area_b * limit.bound_factor);
    if (qa.winding == 0 || qb.winding == 0) {
        return certified_verdict{false, false};
    }
    bool separating = false;
    bool all_blocked = true;
    scan_edges(qa, qb, bound, separating, all_blocked);
    scan_edges(qb, qa, bound, separating, all_blocked);
    return certified_verdict{separating, !separating && all_blocked};
}

}  // namespace obbsat::ref::certified_steps
