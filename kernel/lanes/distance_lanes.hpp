// Distances of separated pairs in lanes, one pair per lane, over the real
// type as the contact lanes (float, or double for the double stores):
// obbsat/ref/distance.hpp's steps without branches (the least of the 32
// candidates a fold of strict compares, so ties go to the first as in the
// reference). Private to each per-ISA object (README.md).
#pragma once

#include "lanes/contact_lanes.hpp"
#include "lanes/lanes.hpp"

namespace obbsat::detail {
namespace {

/// The distance and closest points of each lane's pair.
template <class Arch, class Real>
struct closest_points_lanes {
    real_lanes<Arch, Real> distance, ax, ay, bx, by;
};

/// D1 for corners on one box's faces: the lanes where no face of `faces`
/// separates it from `other`.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_mask<Arch, Real> faces_overlap_lanes(const contact_box_lanes<Arch, Real>& faces,
                                                             const contact_box_lanes<Arch, Real>& other) {
    using batch = real_lanes<Arch, Real>;
    real_mask<Arch, Real> overlap = batch(Real(0)) == batch(Real(0));
    for (int k = 0; k < 4; ++k) {
        auto along = [&](int j) {
            return (faces.nx[k] * (other.vx[j] - faces.vx[k])) + (faces.ny[k] * (other.vy[j] - faces.vy[k]));
        };
        batch least = along(0);
        for (int j = 1; j < 4; ++j) {
            least = min_pick(along(j), least);
        }
        overlap = overlap & (least <= batch(Real(0)));
    }
    return overlap;
}

/// D2 for the edges of `edges` against the vertices of `vertices`, folded
/// into `best` (d2 and the points of A and of B), `first` for the very first.
template <class Arch, class Real>
OBBSAT_LANE_INLINE void edge_candidates_lanes(const contact_box_lanes<Arch, Real>& edges,
                                              const contact_box_lanes<Arch, Real>& vertices, bool edges_are_a,
                                              real_lanes<Arch, Real>* best, bool first) {
    using batch = real_lanes<Arch, Real>;
    const batch zero(Real(0)), one(Real(1));
    for (int k = 0; k < 4; ++k) {
        const int next = (k + 1) & 3;
        const batch sx = edges.vx[k], sy = edges.vy[k];
        const batch ex = edges.vx[next] - sx, ey = edges.vy[next] - sy;
        const batch ee = (ex * ex) + (ey * ey);
        const batch g = one / ee;
        const auto has_length = ee > zero;
        for (int j = 0; j < 4; ++j) {
            const batch px = vertices.vx[j], py = vertices.vy[j];
            batch t = xsimd::select(has_length, (((px - sx) * ex) + ((py - sy) * ey)) * g, zero);
            t = min_pick(max_pick(t, zero), one);
            const batch qx = sx + (t * ex), qy = sy + (t * ey);
            const batch dx = px - qx, dy = py - qy;
            const batch d2 = (dx * dx) + (dy * dy);
            const batch candidate[5] = {d2, edges_are_a ? qx : px, edges_are_a ? qy : py, edges_are_a ? px : qx,
                                        edges_are_a ? py : qy};
            if (first && k == 0 && j == 0) {
                for (int f = 0; f < 5; ++f) {
                    best[f] = candidate[f];
                }
            } else {
                const auto nearer = d2 < best[0];
                for (int f = 0; f < 5; ++f) {
                    best[f] = xsimd::select(nearer, candidate[f], best[f]);
                }
            }
        }
    }
}

/// D1 to D3 for the fields of each lane's pair: poses (cx, cy, hx, hy, c, s)
/// or corners (UL, UR, LR, LL), A's first two fields the origin.
template <class Arch, class Real, bool Corners>
OBBSAT_LANE_INLINE closest_points_lanes<Arch, Real> distance_lanes_of(const real_lanes<Arch, Real>* fa,
                                                                      const real_lanes<Arch, Real>* fb) {
    using batch = real_lanes<Arch, Real>;
    const batch zero(Real(0)), one(Real(1));
    const batch origin_x = fa[0], origin_y = fa[1];
    contact_box_lanes<Arch, Real> a, b;
    real_mask<Arch, Real> collides;
    if constexpr (Corners) {
        a = contact_corner_box<Arch, Real>(fa, origin_x, origin_y);
        b = contact_corner_box<Arch, Real>(fb, origin_x, origin_y);
        collides = faces_overlap_lanes<Arch, Real>(a, b) & faces_overlap_lanes<Arch, Real>(b, a);
    } else {
        // The boxes' inv is not used here.
        a = contact_pose_box<Arch, Real>(fa, origin_x, origin_y, one);
        b = contact_pose_box<Arch, Real>(fb, origin_x, origin_y, one);
        const auto axes = local_axes_lanes<Arch, Real>(fa, fb);
        collides = xsimd::abs(axes.offset[0]) <= axes.reach[0];
        for (int k = 1; k < 4; ++k) {
            collides = collides & (xsimd::abs(axes.offset[k]) <= axes.reach[k]);
        }
    }
    batch best[5] = {zero, zero, zero, zero, zero};  // replaced by the first candidate
    edge_candidates_lanes<Arch, Real>(a, b, true, best, true);
    edge_candidates_lanes<Arch, Real>(b, a, false, best, false);
    return closest_points_lanes<Arch, Real>{
        xsimd::select(collides, zero, xsimd::sqrt(best[0])), xsimd::select(collides, zero, origin_x + best[1]),
        xsimd::select(collides, zero, origin_y + best[2]), xsimd::select(collides, zero, origin_x + best[3]),
        xsimd::select(collides, zero, origin_y + best[4])};
}

}  // namespace
}  // namespace obbsat::detail
