// Method sat4 on one pair per lane: the same IEEE operations, in the same
// order, as obbsat::ref::sat4 (scalar_ref/include/obbsat/ref/sat4.hpp states
// the order). The scalar stops at the first separating axis; here all four
// axes are evaluated and their verdicts combined, which gives the same answer.
#pragma once

#include "lanes.hpp"

namespace obbsat::detail {
namespace {

template <class Arch>
struct sat4_lanes {
    /// min and max of the four corner scalars (x * ax) + (y * ay), folded UL, UR, LR, LL.
    static void project(const quad_lanes<Arch>& q, const lanes<Arch>& ax, const lanes<Arch>& ay,
                        lanes<Arch>& lo, lanes<Arch>& hi) {
        lanes<Arch> s[4];
        for (unsigned k = 0; k < 4; ++k) {
            const lanes<Arch> along_x = q.x(k) * ax;
            const lanes<Arch> along_y = q.y(k) * ay;
            s[k] = along_x + along_y;
        }
        lo = min_pick<Arch>(min_pick<Arch>(min_pick<Arch>(s[UL], s[UR]), s[LR]), s[LL]);
        hi = max_pick<Arch>(max_pick<Arch>(max_pick<Arch>(s[UL], s[UR]), s[LR]), s[LL]);
    }

    /// Overlap on the axis (ax, ay): minB <= maxA and maxB >= minA.
    static lane_mask<Arch> overlap_on(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b,
                                      const lanes<Arch>& ax, const lanes<Arch>& ay) {
        lanes<Arch> min_a, max_a, min_b, max_b;
        project(a, ax, ay, min_a, max_a);
        project(b, ax, ay, min_b, max_b);
        return (min_b <= max_a) & (max_b >= min_a);
    }

    static lane_mask<Arch> collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        // The article's axes: A.UR - A.UL, A.UR - A.LR, B.UL - B.LL, B.UL - B.UR.
        const lane_mask<Arch> on1 =
            overlap_on(a, b, a.x(UR) - a.x(UL), a.y(UR) - a.y(UL));
        const lane_mask<Arch> on2 =
            overlap_on(a, b, a.x(UR) - a.x(LR), a.y(UR) - a.y(LR));
        const lane_mask<Arch> on3 =
            overlap_on(a, b, b.x(UL) - b.x(LL), b.y(UL) - b.y(LL));
        const lane_mask<Arch> on4 =
            overlap_on(a, b, b.x(UL) - b.x(UR), b.y(UL) - b.y(UR));
        return on1 & on2 & on3 & on4;
    }
};

}  // namespace
}  // namespace obbsat::detail
