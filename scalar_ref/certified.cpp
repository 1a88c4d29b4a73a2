#include <obbsat/ref/certified.hpp>

#include <initializer_list>

namespace obbsat::ref {

namespace {

constexpr float min_area = 0x1p-80f;
constexpr float max_area = 0x1p100f;
constexpr float bound_factor = 0x1p-20f;

float min_pick(float u, float v) { return (u < v) ? u : v; }
float max_pick(float u, float v) { return (u > v) ? u : v; }

struct quad_edges {
    point corner[4];
    point edge[4];    // corner[k+1] - corner[k]
    float winding;    // +1 counter-clockwise, -1 clockwise, 0 not proven convex
};

quad_edges edges_of(const rect& r, float own_bound) {
    quad_edges q{{r.ul, r.ur, r.lr, r.ll}, {}, 0.0f};
    for (int k = 0; k < 4; ++k) {
        const point& from = q.corner[k];
        const point& to = q.corner[(k + 1) % 4];
        q.edge[k] = point{to.x - from.x, to.y - from.y};
    }
    bool all_left = true;
    bool all_right = true;
    for (int k = 0; k < 4; ++k) {
        const point& e = q.edge[k];
        const point& next = q.edge[(k + 1) % 4];
        const float turn = (e.x * next.y) - (e.y * next.x);
        all_left = all_left && turn > own_bound;
        all_right = all_right && turn < -own_bound;
    }
    q.winding = all_left ? 1.0f : (all_right ? -1.0f : 0.0f);
    return q;
}

// The orientation of r against edge k of q, sign-flipped for clockwise q so
// that negative always means outside.
float outward_orientation(const quad_edges& q, int k, point r) {
    const point& p = q.corner[k];
    const point& e = q.edge[k];
    const float d = (e.x * (r.y - p.y)) - (e.y * (r.x - p.x));
    return q.winding < 0.0f ? -d : d;
}

// Over the edges of `q` against the corners of `other`: some edge with every
// corner outside (separating), and every edge with some corner inside (blocked).
void scan_edges(const quad_edges& q, const quad_edges& other, float bound, bool& separating,
                bool& all_blocked) {
    for (int k = 0; k < 4; ++k) {
        bool all_outside = true;
        bool any_inside = false;
        for (const point& r : other.corner) {
            const float sd = outward_orientation(q, k, r);
            all_outside = all_outside && sd < -bound;
            any_inside = any_inside || sd > bound;
        }
        separating = separating || all_outside;
        all_blocked = all_blocked && any_inside;
    }
}

struct extent {
    float xmin, xmax, ymin, ymax;

    float area() const { return (xmax - xmin) * (ymax - ymin); }
};

extent extent_of(const rect& r) {
    extent e{r.ul.x, r.ul.x, r.ul.y, r.ul.y};
    for (const point& p : {r.ur, r.lr, r.ll}) {
        e.xmin = min_pick(e.xmin, p.x);
        e.xmax = max_pick(e.xmax, p.x);
        e.ymin = min_pick(e.ymin, p.y);
        e.ymax = max_pick(e.ymax, p.y);
    }
    return e;
}

extent joined(const extent& a, const extent& b) {
    return extent{min_pick(a.xmin, b.xmin), max_pick(a.xmax, b.xmax), min_pick(a.ymin, b.ymin),
                  max_pick(a.ymax, b.ymax)};
}

// NaN (from an infinite width) fails both comparisons: out of range.
bool in_range(float area) { return area >= min_area && area <= max_area; }

}  // namespace

certified_verdict certify(const rect& a, const rect& b) {
    const extent ea = extent_of(a);
    const extent eb = extent_of(b);
    const float area_a = ea.area();
    const float area_b = eb.area();
    const float area = joined(ea, eb).area();
    if (!(in_range(area) && area_a >= min_area && area_b >= min_area)) {
        return certified_verdict{false, false};
    }
    const float bound = area * bound_factor;
    const quad_edges qa = edges_of(a, area_a * bound_factor);
    const quad_edges qb = edges_of(b, area_b * bound_factor);
    if (qa.winding == 0.0f || qb.winding == 0.0f) {
        return certified_verdict{false, false};
    }
    bool separating = false;
    bool all_blocked = true;
    scan_edges(qa, qb, bound, separating, all_blocked);
    scan_edges(qb, qa, bound, separating, all_blocked);
    return certified_verdict{separating, !separating && all_blocked};
}

}  // namespace obbsat::ref
