// Whether two convex quadrilaterals with integer corners meet, decided
// exactly in 64-bit integers and without any separating axis: two closed
// convex polygons meet iff a corner of one lies in the other or an edge of one
// meets an edge of the other. An oracle independent of the method under test.
#pragma once

#include <obbsat/rect.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace obbsat::test_support {

struct lattice_point {
    std::int64_t x;
    std::int64_t y;
};

inline std::int64_t to_integer(float v) {
    if (!(std::fabs(v) < 1.0e9f) || std::nearbyint(v) != v) {
        throw std::invalid_argument("exact_intersection needs integer corners below 1e9");
    }
    return static_cast<std::int64_t>(v);
}

inline std::array<lattice_point, 4> lattice_corners(const rect& r) {
    const point corners[4] = {r.ul, r.ur, r.lr, r.ll};
    std::array<lattice_point, 4> out{};
    for (unsigned k = 0; k < 4; ++k) {
        out[k] = lattice_point{to_integer(corners[k].x), to_integer(corners[k].y)};
    }
    return out;
}

/// Twice the signed area of (p, q, r): > 0 left turn, < 0 right turn, 0 collinear.
inline std::int64_t orientation(lattice_point p, lattice_point q, lattice_point r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

/// True iff r, known to be collinear with p and q, lies within their bounding box.
inline bool within_box(lattice_point p, lattice_point q, lattice_point r) {
    const bool in_x = (p.x <= r.x && r.x <= q.x) || (q.x <= r.x && r.x <= p.x);
    const bool in_y = (p.y <= r.y && r.y <= q.y) || (q.y <= r.y && r.y <= p.y);
    return in_x && in_y;
}

/// Closed segments pq and rs share at least one point.
inline bool segments_meet(lattice_point p, lattice_point q, lattice_point r, lattice_point s) {
    const std::int64_t o1 = orientation(p, q, r);
    const std::int64_t o2 = orientation(p, q, s);
    const std::int64_t o3 = orientation(r, s, p);
    const std::int64_t o4 = orientation(r, s, q);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
        return true;
    }
    return (o1 == 0 && within_box(p, q, r)) || (o2 == 0 && within_box(p, q, s)) ||
           (o3 == 0 && within_box(r, s, p)) || (o4 == 0 && within_box(r, s, q));
}

/// p lies in the closed convex quadrilateral `quad` (either winding, non-degenerate).
inline bool inside_or_on(const std::array<lattice_point, 4>& quad, lattice_point p) {
    bool any_left = false;
    bool any_right = false;
    for (unsigned k = 0; k < 4; ++k) {
        const std::int64_t o = orientation(quad[k], quad[(k + 1) % 4], p);
        any_left = any_left || o > 0;
        any_right = any_right || o < 0;
    }
    return !(any_left && any_right);
}

/// The closed convex quadrilaterals a and b (integer corners) share a point.
inline bool convex_quads_meet(const rect& a, const rect& b) {
    const auto qa = lattice_corners(a);
    const auto qb = lattice_corners(b);
    for (unsigned k = 0; k < 4; ++k) {
        if (inside_or_on(qa, qb[k]) || inside_or_on(qb, qa[k])) {
            return true;
        }
    }
    for (unsigned i = 0; i < 4; ++i) {
        for (unsigned j = 0; j < 4; ++j) {
            if (segments_meet(qa[i], qa[(i + 1) % 4], qb[j], qb[(j + 1) % 4])) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace obbsat::test_support
