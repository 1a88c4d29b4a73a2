#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>
#include <obbsat/ref/local.hpp>

#include <cmath>

namespace obbsat::ref {

namespace {

float dot(point p, point q) { return (p.x * q.x) + (p.y * q.y); }
point minus(point p, point q) { return point{p.x - q.x, p.y - q.y}; }

/// D1 for corners: no face of either box separates it from the other.
bool faces_overlap(const contact_box& faces, const contact_box& other) {
    for (int k = 0; k < 4; ++k) {
        float least = dot(faces.n[k], minus(other.v[0], faces.v[k]));
        for (int j = 1; j < 4; ++j) {
            const float along = dot(faces.n[k], minus(other.v[j], faces.v[k]));
            least = along < least ? along : least;
        }
        if (!(least <= 0.0f)) {
            return false;
        }
    }
    return true;
}

/// The best candidate of step D2 so far.
struct nearest {
    float d2;
    point on_a, on_b;
};

/// D2 for the edges of `edges` against the vertices of `vertices`; `edges_are_a`
/// says which box the edges belong to. Updates `best` (or sets it, when `first`).
void edge_candidates(const contact_box& edges, const contact_box& vertices, bool edges_are_a, nearest& best,
                     bool& first) {
    for (int k = 0; k < 4; ++k) {
        const point start = edges.v[k];
        const point e = minus(edges.v[(k + 1) & 3], start);
        const float ee = dot(e, e);
        for (int j = 0; j < 4; ++j) {
            const point p = vertices.v[j];
            float t = ee > 0.0f ? dot(minus(p, start), e) * (1.0f / ee) : 0.0f;
            t = t > 0.0f ? t : 0.0f;
            t = t < 1.0f ? t : 1.0f;
            const point q{start.x + (t * e.x), start.y + (t * e.y)};
            const point d = minus(p, q);
            const float d2 = (d.x * d.x) + (d.y * d.y);
            if (first || d2 < best.d2) {
                best = edges_are_a ? nearest{d2, q, p} : nearest{d2, p, q};
                first = false;
            }
        }
    }
}

/// D2 and D3 for separated boxes.
closest_points closest_of(const contact_box& a, const contact_box& b, point origin) {
    nearest best{};
    bool first = true;
    edge_candidates(a, b, true, best, first);
    edge_candidates(b, a, false, best, first);
    return closest_points{std::sqrt(best.d2), origin.x + best.on_a.x, origin.y + best.on_a.y,
                          origin.x + best.on_b.x, origin.y + best.on_b.y};
}

}  // namespace

closest_points distance_of(const rect_pose& a, const rect_pose& b) {
    if (local(a, b)) {
        return closest_points{};
    }
    const point origin = a.center;
    return closest_of(contact_box_of(a, origin), contact_box_of(b, origin), origin);
}

closest_points distance_of(const rect& a, const rect& b) {
    const point origin = a.ul;
    const contact_box box_a = contact_box_of(a, origin), box_b = contact_box_of(b, origin);
    if (faces_overlap(box_a, box_b) && faces_overlap(box_b, box_a)) {
        return closest_points{};
    }
    return closest_of(box_a, box_b, origin);
}

}  // namespace obbsat::ref
