// The article's test on one pair per lane: the same IEEE operations, in the
// same order, as the scalar reference (scalar_ref/include/obbsat/ref/sat4.hpp
// states the order), over a batch of float (sat4, sat4_centered) or of double
// (sat4_double). The scalar stops at the first separating axis; here all four
// axes are evaluated and their verdicts combined, which gives the same answer.
#pragma once

#include "lanes/lanes.hpp"

namespace obbsat::detail {
namespace {

template <class Batch>
struct sat4_steps {
    using mask = typename Batch::batch_bool_type;

    /// min and max of four corner scalars, folded UL, UR, LR, LL.
    static OBBSAT_LANE_INLINE void fold(const Batch (&s)[4], Batch& lo, Batch& hi) {
        lo = min_pick(min_pick(min_pick(s[UL], s[UR]), s[LR]), s[LL]);
        hi = max_pick(max_pick(max_pick(s[UL], s[UR]), s[LR]), s[LL]);
    }

    /// min and max of the four corner scalars (x * ax) + (y * ay).
    static OBBSAT_LANE_INLINE void project(const quad<Batch>& q, const Batch& ax, const Batch& ay, Batch& lo, Batch& hi) {
        Batch s[4];
        for (unsigned k = 0; k < 4; ++k) {
            const Batch along_x = q.x(k) * ax;
            const Batch along_y = q.y(k) * ay;
            s[k] = along_x + along_y;
        }
        fold(s, lo, hi);
    }

    /// Overlap on the axis (ax, ay): minB <= maxA and maxB >= minA.
    static OBBSAT_LANE_INLINE mask overlap_on(const quad<Batch>& a, const quad<Batch>& b, const Batch& ax, const Batch& ay) {
        Batch min_a, max_a, min_b, max_b;
        project(a, ax, ay, min_a, max_a);
        project(b, ax, ay, min_b, max_b);
        return (min_b <= max_a) & (max_b >= min_a);
    }

    static OBBSAT_LANE_INLINE mask collide(const quad<Batch>& a, const quad<Batch>& b) {
        // The article's axes: A.UR - A.UL, A.UR - A.LR, B.UL - B.LL, B.UL - B.UR.
        const mask on1 = overlap_on(a, b, a.x(UR) - a.x(UL), a.y(UR) - a.y(UL));
        const mask on2 = overlap_on(a, b, a.x(UR) - a.x(LR), a.y(UR) - a.y(LR));
        // When A's two axes already separate every lane, B's axes cannot
        // change the verdict: skip them (pays on sparse candidate lists).
        if (!xsimd::any(on1 & on2)) {
            return on1 & on2;
        }
        const mask on3 = overlap_on(a, b, b.x(UL) - b.x(LL), b.y(UL) - b.y(LL));
        const mask on4 = overlap_on(a, b, b.x(UL) - b.x(UR), b.y(UL) - b.y(UR));
        return on1 & on2 & on3 & on4;
    }
};

/// Method sat4: the steps on the float corners as given.
template <class Arch>
struct sat4_lanes {
    static constexpr bool has_slow_path = false;
    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        return lane_verdicts{lane_bits(sat4_steps<lanes<Arch>>::collide(a, b)), 0};
    }
};

}  // namespace
}  // namespace obbsat::detail
