// The distance reference (obbsat/ref/distance.hpp), each step one template
// over the scalar type: float for the float boxes, double for the double ones.
#include "contact_shapes.hpp"

#include <obbsat/ref/distance.hpp>

#include <cmath>

namespace obbsat::ref {

namespace {

using contact_steps::dot;
using contact_steps::minus;
using contact_steps::shapes;

/// D1 for corners: no face of either box separates it from the other.
template <class Real, class Box>
bool faces_overlap(const Box& faces, const Box& other) {
    for (int k = 0; k < 4; ++k) {
        Real least = dot(faces.n[k], minus(other.v[0], faces.v[k]));
        for (int j = 1; j < 4; ++j) {
            const Real along = dot(faces.n[k], minus(other.v[j], faces.v[k]));
            least = along < least ? along : least;
        }
        if (!(least <= Real(0))) {
            return false;
        }
    }
    return true;
}

/// The best candidate of step D2 so far.
template <class Real>
struct nearest {
    Real d2;
    typename shapes<Real>::point_type on_a, on_b;
};

/// D2 for the edges of `edges` against the vertices of `vertices`; `edges_are_a`
/// says which box the edges belong to. Updates `best` (or sets it, when `first`).
template <class Real, class Box>
void edge_candidates(const Box& edges, const Box& vertices, bool edges_are_a, nearest<Real>& best, bool& first) {
    using point_type = typename shapes<Real>::point_type;
    for (int k = 0; k < 4; ++k) {
        const point_type start = edges.v[k];
        const point_type e = minus(edges.v[(k + 1) & 3], start);
        const Real ee = dot(e, e);
        for (int j = 0; j < 4; ++j) {
            const point_type p = vertices.v[j];
            Real t = ee > Real(0) ? dot(minus(p, start), e) * (Real(1) / ee) : Real(0);
            t = t > Real(0) ? t : Real(0);
            t = t < Real(1) ? t : Real(1);
            const point_type q{start.x + (t * e.x), start.y + (t * e.y)};
            const point_type d = minus(p, q);
            const Real d2 = (d.x * d.x) + (d.y * d.y);
            if (first || d2 < best.d2) {
                best = edges_are_a ? nearest<Real>{d2, q, p} : nearest<Real>{d2, p, q};
                first = false;
            }
        }
    }
}

/// D2 and D3 for separated boxes.
template <class Real>
typename shapes<Real>::closest closest_of(const typename shapes<Real>::box& a, const typename shapes<Real>::box& b,
                                          typename shapes<Real>::point_type origin) {
    nearest<Real> best{};
    bool first = true;
    edge_candidates<Real>(a, b, true, best, first);
    edge_candidates<Real>(b, a, false, best, first);
    return typename shapes<Real>::closest{std::sqrt(best.d2), origin.x + best.on_a.x, origin.y + best.on_a.y,
                                          origin.x + best.on_b.x, origin.y + best.on_b.y};
}

template <class Real>
typename shapes<Real>::closest poses_distance(const typename shapes<Real>::pose& a,
                                              const typename shapes<Real>::pose& b) {
    if (local(a, b)) {
        return typename shapes<Real>::closest{};
    }
    const auto origin = a.center;
    return closest_of<Real>(contact_box_of(a, origin), contact_box_of(b, origin), origin);
}

template <class Real>
typename shapes<Real>::closest quads_distance(const typename shapes<Real>::quad& a,
                                              const typename shapes<Real>::quad& b) {
    const auto origin = a.ul;
    const auto box_a = contact_box_of(a, origin), box_b = contact_box_of(b, origin);
    if (faces_overlap<Real>(box_a, box_b) && faces_overlap<Real>(box_b, box_a)) {
        return typename shapes<Real>::closest{};
    }
    return closest_of<Real>(box_a, box_b, origin);
}

}  // namespace

closest_points distance_of(const rect_pose& a, const rect_pose& b) { return poses_distance<float>(a, b); }
closest_points64 distance_of(const rect_pose64& a, const rect_pose64& b) { return poses_distance<double>(a, b); }
closest_points distance_of(const rect& a, const rect& b) { return quads_distance<float>(a, b); }
closest_points64 distance_of(const rect64& a, const rect64& b) { return quads_distance<double>(a, b); }

}  // namespace obbsat::ref
