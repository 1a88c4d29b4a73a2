// The certified separating-edge test on one pair per lane: the same float
// (or double) operations, in the same order, as obbsat::ref::certify
// (scalar_ref/include/obbsat/ref/certified.hpp and certified64.hpp state
// them), and method exact on float corners built on it: undecided lanes are
// settled by the exact oracle, one pair at a time.
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/oracle/contact.hpp>

namespace obbsat::detail {
namespace {

/// The guard and the bound of one precision, as scalar_ref/certified.cpp and
/// certified64.cpp give them to the reference.
template <class Real>
struct certified_lane_limits;

template <>
struct certified_lane_limits<float> {
    static constexpr float min_area = 0x1p-80f;
    static constexpr float max_area = 0x1p100f;
    static constexpr float bound_factor = 0x1p-20f;
};

template <>
struct certified_lane_limits<double> {
    static constexpr double min_area = 0x1p-900;
    static constexpr double max_area = 0x1p1000;
    static constexpr double bound_factor = 0x1p-49;
};

/// The steps over corners of type Real (float or double), one pair per lane.
template <class Arch, class Real = float>
struct certified_steps {
    using batch = xsimd::batch<Real, Arch>;
    using mask = xsimd::batch_bool<Real, Arch>;
    using corners = quad<batch>;
    using limits = certified_lane_limits<Real>;

    struct quad_edges {
        batch ex[4], ey[4];  // edge k: corner k+1 - corner k
        batch flip;          // -0.0 where the winding is clockwise, +0.0 otherwise
        mask convex;         // proven strictly convex
    };

    struct verdict {
        mask separated;
        mask intersecting;
    };

    /// Per-coordinate extent of a set of corners.
    struct extent {
        batch xmin, xmax, ymin, ymax;

        batch area() const { return (xmax - xmin) * (ymax - ymin); }
    };

    static OBBSAT_LANE_INLINE extent extent_of(const corners& q) {
        extent e{q.x(UL), q.x(UL), q.y(UL), q.y(UL)};
        for (unsigned k = 1; k < 4; ++k) {
            e.xmin = min_pick(e.xmin, q.x(k));
            e.xmax = max_pick(e.xmax, q.x(k));
            e.ymin = min_pick(e.ymin, q.y(k));
            e.ymax = max_pick(e.ymax, q.y(k));
        }
        return e;
    }

    static OBBSAT_LANE_INLINE extent joined(const extent& a, const extent& b) {
        return extent{min_pick(a.xmin, b.xmin), max_pick(a.xmax, b.xmax), min_pick(a.ymin, b.ymin),
                      max_pick(a.ymax, b.ymax)};
    }

    static OBBSAT_LANE_INLINE quad_edges edges_of(const corners& q, const batch& bound) {
        quad_edges out;
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned next = (k + 1) % 4;
            out.ex[k] = q.x(next) - q.x(k);
            out.ey[k] = q.y(next) - q.y(k);
        }
        const batch neg_bound = -bound;
        mask all_left(true), all_right(true);
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned next = (k + 1) % 4;
            const batch turn = (out.ex[k] * out.ey[next]) - (out.ey[k] * out.ex[next]);
            all_left = all_left & (turn > bound);
            all_right = all_right & (turn < neg_bound);
        }
        out.convex = all_left | all_right;
        out.flip = xsimd::select(all_right, batch(Real(-0.0)), batch(Real(0.0)));
        return out;
    }

    /// Edges of q against the corners of `other`: some edge with every corner
    /// outside (separating) and every edge with a corner inside (blocked).
    static OBBSAT_LANE_INLINE void scan_edges(const corners& q, const quad_edges& qe,
                                              const corners& other, const batch& bound,
                                              mask& separating, mask& all_blocked) {
        // Every corner outside iff the largest outward orientation is below
        // -bound; some corner inside iff it is above bound. On a decidable
        // lane no orientation is NaN, so the max decides both exactly as the
        // reference's per-corner comparisons do.
        const batch neg_bound = -bound;
        for (unsigned k = 0; k < 4; ++k) {
            batch largest;
            for (unsigned r = 0; r < 4; ++r) {
                const batch d = (qe.ex[k] * (other.y(r) - q.y(k))) - (qe.ey[k] * (other.x(r) - q.x(k)));
                const batch sd = d ^ qe.flip;  // negated for clockwise quads: exact
                largest = r == 0 ? sd : max_pick(largest, sd);
            }
            separating = separating | (largest < neg_bound);
            all_blocked = all_blocked & (largest > bound);
        }
    }

    static OBBSAT_LANE_INLINE verdict certify(const corners& a, const corners& b) {
        const extent xa = extent_of(a);
        const extent xb = extent_of(b);
        const batch area_a = xa.area();
        const batch area_b = xb.area();
        const batch area = joined(xa, xb).area();
        const batch min_area(limits::min_area);
        const batch factor(limits::bound_factor);
        const mask in_range =
            (area >= min_area) & (area <= batch(limits::max_area)) & (area_a >= min_area) & (area_b >= min_area);
        const batch bound = area * factor;

        const quad_edges ea = edges_of(a, area_a * factor);
        const quad_edges eb = edges_of(b, area_b * factor);
        const mask decidable = in_range & ea.convex & eb.convex;

        mask separating(false), all_blocked(true);
        scan_edges(a, ea, b, bound, separating, all_blocked);
        scan_edges(b, eb, a, bound, separating, all_blocked);
        return verdict{decidable & separating, decidable & ~separating & all_blocked};
    }
};

/// Method exact: proven lanes from the fast path, the rest from the oracle.
template <class Arch>
struct exact_lanes {
    static constexpr bool has_slow_path = true;
    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        const auto v = certified_steps<Arch>::certify(a, b);
        return lane_verdicts{lane_bits(v.intersecting), lane_bits(~(v.separated | v.intersecting))};
    }
    static bool decide_exactly(const rect& a, const rect& b) { return oracle::intersects(a, b); }
};

}  // namespace
}  // namespace obbsat::detail
