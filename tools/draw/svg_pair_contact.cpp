#include "draw/svg_pair_contact.hpp"

#include <obbsat/oracle/orientation.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace obbsat::svg {

namespace {

// The inset shows about this many gaps (or depths) across...
constexpr double inset_gaps_across = 20.0;
// ...and at least this many float ulps, so a contact without any gap still
// shows the grid it lies on.
constexpr double inset_min_ulps = 16.0;
// An inset that magnifies less than this adds nothing to the main view.
constexpr double inset_min_zoom = 4.0;

std::array<point, 4> corners_of(const rect& r) { return {r.ul, r.ur, r.lr, r.ll}; }

struct vec {
    double x;
    double y;
};

// A corner in double: a float corner exactly, a double corner as it is.
vec vec_of(point p) { return {p.x, p.y}; }
vec vec_of(world_point p) { return {p.x, p.y}; }

vec operator-(vec u, vec v) { return {u.x - v.x, u.y - v.y}; }
vec operator+(vec u, vec v) { return {u.x + v.x, u.y + v.y}; }
vec operator*(double s, vec v) { return {s * v.x, s * v.y}; }
double dot(vec u, vec v) { return u.x * v.x + u.y * v.y; }
double cross(vec u, vec v) { return u.x * v.y - u.y * v.x; }
double length(vec v) { return std::hypot(v.x, v.y); }

// The closest points of two outline segments, or where they meet.
struct segment_contact {
    vec on_a;
    vec on_b;
    double distance;
    bool meet;
    // Length of the stretch along which the segments are this close: a
    // collinear overlap, or parallel edges; 0 for a single point.
    double stretch;
};

// The point of segment [p, q] closest to r.
vec closest_on_segment(vec p, vec q, vec r) {
    const vec d = q - p;
    const double dd = dot(d, d);
    if (dd == 0.0) {
        return p;
    }
    const double t = std::clamp(dot(r - p, d) / dd, 0.0, 1.0);
    return p + t * d;
}

// Which side of the line p -> q the point r lies on: exact for float
// corners, in double for double ones.
int orientation_of(point p, point q, point r) { return oracle::orientation(p, q, r); }
int orientation_of(world_point p, world_point q, world_point r) {
    const double turn = cross(vec_of(q) - vec_of(p), vec_of(r) - vec_of(p));
    return (turn > 0.0) - (turn < 0.0);
}

// True iff r, already known collinear with p and q, lies on the closed segment.
template <class Corner>
bool within_segment(Corner p, Corner q, Corner r) {
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
}

// Two parallel edges are closest along a whole stretch; its middle shows the
// gap better than the stretch's end, which is a corner where labels crowd.
// (For the picture only: a tolerance is harmless here.)
void centre_parallel_stretch(vec pa0, vec pa1, vec pb0, vec pb1, segment_contact& best) {
    const vec d = pa1 - pa0;
    const double dd = dot(d, d);
    if (dd == 0.0) {
        return;
    }
    const double t0 = dot(pb0 - pa0, d) / dd;
    const double t1 = dot(pb1 - pa0, d) / dd;
    const double lo = std::max(0.0, std::min(t0, t1));
    const double hi = std::min(1.0, std::max(t0, t1));
    if (!(hi > lo)) {
        return;
    }
    const vec from = pa0 + lo * d;
    const vec to = pa0 + hi * d;
    const double d_from = length(closest_on_segment(pb0, pb1, from) - from);
    const double d_to = length(closest_on_segment(pb0, pb1, to) - to);
    const double tolerance = 1e-9 * std::max(d_from, d_to);
    if (std::fabs(d_from - d_to) > tolerance || std::fabs(d_from - best.distance) > tolerance) {
        return;
    }
    const vec middle = pa0 + (0.5 * (lo + hi)) * d;
    best.on_a = middle;
    best.on_b = closest_on_segment(pb0, pb1, middle);
    best.stretch = length(to - from);
}

class outline_geometry {
public:
    explicit outline_geometry(world_point center) : center_(center) {}

    template <class Corner>
    vec relative(Corner p) const {
        return vec_of(p) - vec{center_.x, center_.y};
    }

    // Segment [a0, a1] of A against [b0, b1] of B.
    template <class Corner>
    segment_contact between(Corner a0, Corner a1, Corner b0, Corner b1) const {
        const int side_b0 = orientation_of(a0, a1, b0);
        const int side_b1 = orientation_of(a0, a1, b1);
        const int side_a0 = orientation_of(b0, b1, a0);
        const int side_a1 = orientation_of(b0, b1, a1);
        const vec pa0 = relative(a0), pa1 = relative(a1), pb0 = relative(b0), pb1 = relative(b1);
        if (side_b0 * side_b1 < 0 && side_a0 * side_a1 < 0) {
            const vec at = crossing(a0, a1, b0, b1);
            return {at, at, 0.0, true, 0.0};
        }
        // Endpoints lying on the other segment: a touch, or the ends of a
        // collinear overlap.
        vec touching[4];
        int count = 0;
        if (side_b0 == 0 && within_segment(a0, a1, b0)) touching[count++] = pb0;
        if (side_b1 == 0 && within_segment(a0, a1, b1)) touching[count++] = pb1;
        if (side_a0 == 0 && within_segment(b0, b1, a0)) touching[count++] = pa0;
        if (side_a1 == 0 && within_segment(b0, b1, a1)) touching[count++] = pa1;
        if (count > 0) {
            vec from = touching[0];
            vec to = touching[0];
            double longest = 0.0;
            for (int i = 0; i < count; ++i) {
                for (int j = i + 1; j < count; ++j) {
                    const double d = length(touching[j] - touching[i]);
                    if (d > longest) {
                        longest = d;
                        from = touching[i];
                        to = touching[j];
                    }
                }
            }
            const vec middle = from + 0.5 * (to - from);
            return {middle, middle, 0.0, true, longest};
        }
        segment_contact best{pa0, closest_on_segment(pb0, pb1, pa0), 0.0, false, 0.0};
        best.distance = length(best.on_b - best.on_a);
        const auto consider = [&best](vec on_a, vec on_b) {
            const double d = length(on_b - on_a);
            if (d < best.distance) {
                best.on_a = on_a;
                best.on_b = on_b;
                best.distance = d;
            }
        };
        consider(pa1, closest_on_segment(pb0, pb1, pa1));
        consider(closest_on_segment(pa0, pa1, pb0), pb0);
        consider(closest_on_segment(pa0, pa1, pb1), pb1);
        centre_parallel_stretch(pa0, pa1, pb0, pb1, best);
        return best;
    }

    world_point absolute(vec v) const { return {center_.x + v.x, center_.y + v.y}; }

private:
    // Where [a0, a1] crosses [b0, b1], given that the signs say they cross
    // at one point inside both. The edge vectors come from the corners
    // themselves: measured from the centre, a short edge beside a
    // huge one (corners 1e17 and 1 apart) rounds to nothing, and the
    // intersection to 0 / 0. Rounding may still put the parameter a little
    // outside the segment, or (edges parallel after rounding) nowhere: it is
    // kept within the segment, as the exact point is.
    template <class Corner>
    vec crossing(Corner a0, Corner a1, Corner b0, Corner b1) const {
        const vec da = vec_of(a1) - vec_of(a0);
        const vec db = vec_of(b1) - vec_of(b0);
        const double t = cross(vec_of(b0) - vec_of(a0), db) / cross(da, db);
        const double inside = t >= 0.0 ? std::min(t, 1.0) : 0.0;  // NaN counts as 0
        return relative(a0) + inside * (relative(a1) - relative(a0));
    }

    world_point center_;
};

// How far the interiors overlap: the smallest overlap of the two rects'
// extents over the normals of all eight edges (the penetration depth of two
// convex quads), in double.
template <class Corner>
double overlap_depth(const std::array<Corner, 4>& fa, const std::array<Corner, 4>& fb,
                     const outline_geometry& geometry) {
    std::array<vec, 4> ca, cb;
    for (std::size_t i = 0; i < 4; ++i) {
        ca[i] = geometry.relative(fa[i]);
        cb[i] = geometry.relative(fb[i]);
    }
    double depth = HUGE_VAL;
    for (const auto* quad : {&ca, &cb}) {
        for (std::size_t k = 0; k < 4; ++k) {
            const vec edge = (*quad)[(k + 1) % 4] - (*quad)[k];
            const double edge_length = length(edge);
            if (edge_length == 0.0) {
                continue;
            }
            const vec normal{-edge.y / edge_length, edge.x / edge_length};
            double a_min = HUGE_VAL, a_max = -HUGE_VAL, b_min = HUGE_VAL, b_max = -HUGE_VAL;
            for (std::size_t i = 0; i < 4; ++i) {
                a_min = std::min(a_min, dot(ca[i], normal));
                a_max = std::max(a_max, dot(ca[i], normal));
                b_min = std::min(b_min, dot(cb[i], normal));
                b_max = std::max(b_max, dot(cb[i], normal));
            }
            depth = std::min(depth, std::max(0.0, std::min(a_max - b_min, b_max - a_min)));
        }
    }
    return depth == HUGE_VAL ? 0.0 : depth;
}

}  // namespace

double float_spacing(double magnitude) {
    if (!(magnitude >= 0x1p-126)) {
        return 0x1p-149;
    }
    int exponent = 0;
    std::frexp(magnitude, &exponent);
    return std::ldexp(1.0, exponent - 24);
}

double double_spacing(double magnitude) {
    if (!(magnitude >= 0x1p-1022)) {
        return 0x1p-1074;
    }
    int exponent = 0;
    std::frexp(magnitude, &exponent);
    return std::ldexp(1.0, exponent - 53);
}

namespace {

// The spacing of `values` at `p`, a point measured from the world point `origin`.
double spacing_at(world_point origin, world_point p, value_type values) {
    const double magnitude = std::max(std::fabs(origin.x + p.x), std::fabs(origin.y + p.y));
    return values == value_type::float64 ? double_spacing(magnitude) : float_spacing(magnitude);
}

template <class Corner>
contact_view contact_of(const std::array<Corner, 4>& fa, const std::array<Corner, 4>& fb, oracle::contact exact,
                        world_point origin, value_type values) {
    contact_view view;
    view.ulp_name = values == value_type::float64 ? "double" : "float";
    double x_min = HUGE_VAL, x_max = -HUGE_VAL, y_min = HUGE_VAL, y_max = -HUGE_VAL;
    for (const auto* quad : {&fa, &fb}) {
        for (const Corner& corner : *quad) {
            const vec p = vec_of(corner);
            x_min = std::min(x_min, p.x);
            x_max = std::max(x_max, p.x);
            y_min = std::min(y_min, p.y);
            y_max = std::max(y_max, p.y);
        }
    }
    view.center = {0.5 * x_min + 0.5 * x_max, 0.5 * y_min + 0.5 * y_max};
    view.size = std::max(x_max - x_min, y_max - y_min);
    if (view.size == 0.0) {
        // Eight equal corners: show a few ulps around them.
        view.size = inset_min_ulps * spacing_at(origin, view.center, values);
    }

    const outline_geometry geometry(view.center);
    segment_contact best{};
    bool first = true;
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            const segment_contact c =
                geometry.between(fa[i], fa[(i + 1) % 4], fb[j], fb[(j + 1) % 4]);
            // Of equally close features, the longest stretch shows best.
            const double tolerance = 1e-9 * best.distance;
            const bool better = first || (c.meet && !best.meet) ||
                                (c.meet == best.meet && c.distance < best.distance - tolerance) ||
                                (c.meet == best.meet && std::fabs(c.distance - best.distance) <= tolerance &&
                                 c.stretch > best.stretch);
            if (better) {
                best = c;
                first = false;
            }
        }
    }
    view.closest_a = geometry.absolute(best.on_a);
    view.closest_b = geometry.absolute(best.on_b);
    view.outlines_meet = best.meet;
    view.distance = best.meet ? 0.0 : best.distance;
    view.depth = exact == oracle::contact::overlapping ? overlap_depth(fa, fb, geometry) : 0.0;

    const double limit = grazing_fraction * view.size;
    const bool grazing = view.outlines_meet ? view.depth < limit : view.distance < limit;
    if (grazing) {
        const vec middle = 0.5 * (best.on_a + best.on_b);
        view.inset_center = geometry.absolute(middle);
        const double measure = view.outlines_meet ? view.depth : view.distance;
        view.inset_ulp = spacing_at(origin, view.inset_center, values);
        view.inset_span = std::max(inset_gaps_across * measure, inset_min_ulps * view.inset_ulp);
        view.has_inset = view.inset_span * inset_min_zoom <= view.size;
    }
    return view;
}

}  // namespace

contact_view view_of_contact(const rect& a, const rect& b, oracle::contact exact) {
    return contact_of(corners_of(a), corners_of(b), exact, world_point{0.0, 0.0}, value_type::float32);
}

contact_view view_of_contact(const std::array<world_point, 4>& a, const std::array<world_point, 4>& b,
                             oracle::contact exact, world_point origin, value_type values) {
    return contact_of(a, b, exact, origin, values);
}

}  // namespace obbsat::svg
