// Rectangles built for tests from edge vectors, bounds and transformations.
//
// Everything here uses float or double basic arithmetic only (no sin, cos),
// so the same calls give the same bytes on every machine: the golden digest
// of test_backends depends on it. With small integer inputs every float
// operation is exact, which is what the hand-worked cases rely on.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::test_support {

inline point plus(point p, point q) { return point{p.x + q.x, p.y + q.y}; }

inline point minus(point p, point q) { return point{p.x - q.x, p.y - q.y}; }

inline point scaled(point p, float factor) { return point{p.x * factor, p.y * factor}; }

/// Bounds [x0, x1] x [y0, y1] with UL at (x0, y1), winding clockwise (y up).
inline rect axis_aligned(float x0, float y0, float x1, float y1) {
    return rect{{x0, y1}, {x1, y1}, {x1, y0}, {x0, y0}};
}

/// The parallelogram LL = origin, LR = origin + u, UR = origin + u + v, UL = origin + v.
inline rect from_edges(point origin, point u, point v) {
    return rect{plus(origin, v), plus(plus(origin, u), v), plus(origin, u), origin};
}

/// The rectangle on integer edge vectors u = (a, b) and v = (-k*b, k*a) at `origin`:
/// v is u turned a quarter to the left and stretched k times, so all corners are
/// integers when the origin is.
inline rect integer_rect(point origin, int a, int b, int k) {
    const point u{static_cast<float>(a), static_cast<float>(b)};
    const point v{static_cast<float>(-k * b), static_cast<float>(k * a)};
    return from_edges(origin, u, v);
}

/// The same quadrilateral walked the other way round (UL stays UL).
inline rect reversed_winding(const rect& r) { return rect{r.ul, r.ll, r.lr, r.ur}; }

/// The same quadrilateral with every label moved one corner on (UL takes UR's place).
inline rect relabelled(const rect& r) { return rect{r.ur, r.lr, r.ll, r.ul}; }

inline rect translated(const rect& r, point by) {
    return rect{plus(r.ul, by), plus(r.ur, by), plus(r.lr, by), plus(r.ll, by)};
}

/// Every coordinate multiplied by `factor` (exact when factor is a power of two
/// and nothing underflows).
inline rect scaled(const rect& r, float factor) {
    return rect{scaled(r.ul, factor), scaled(r.ur, factor), scaled(r.lr, factor),
                scaled(r.ll, factor)};
}

/// Every corner at `p`: a rectangle of zero size.
inline rect point_rect(point p) { return rect{p, p, p, p}; }

/// A rectangle of zero width from p to q: UL = LL = p, UR = LR = q.
inline rect segment_rect(point p, point q) { return rect{p, q, q, p}; }

/// Center (cx, cy), half extents (hx, hy), turned by the unit vector (c, s),
/// computed in double and rounded to float once per coordinate.
inline rect turned_rect(double cx, double cy, double hx, double hy, double c, double s) {
    auto corner = [&](double lx, double ly) {
        return point{static_cast<float>(cx + (c * lx - s * ly)),
                     static_cast<float>(cy + (s * lx + c * ly))};
    };
    return rect{corner(-hx, hy), corner(hx, hy), corner(hx, -hy), corner(-hx, -hy)};
}

/// The unit vector at the angle whose half-angle tangent is t, from the rational
/// parametrisation of the circle: ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)).
/// For small t the angle is 2t radians to within t^3.
struct turn {
    double c;
    double s;
};

inline turn turn_from_half_tangent(double t) {
    return turn{(1.0 - t * t) / (1.0 + t * t), (2.0 * t) / (1.0 + t * t)};
}

}  // namespace obbsat::test_support
