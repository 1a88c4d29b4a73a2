// Method sat4_centered on one pair per lane: every corner of A and B moved by
// -A.UL (one float subtraction per coordinate), then sat4's steps, exactly as
// scalar_ref/include/obbsat/ref/sat4_centered.hpp defines it.
#pragma once

#include "lanes/sat4_lanes.hpp"

namespace obbsat::detail {
namespace {

template <class Arch>
struct sat4_centered_lanes {
    static constexpr bool has_slow_path = false;
    static OBBSAT_LANE_INLINE quad_lanes<Arch> moved(const quad_lanes<Arch>& q, const lanes<Arch>& ox, const lanes<Arch>& oy) {
        quad_lanes<Arch> out;
        for (unsigned k = 0; k < 4; ++k) {
            out.c[2 * k] = q.x(k) - ox;
            out.c[2 * k + 1] = q.y(k) - oy;
        }
        return out;
    }

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        const lanes<Arch> ox = a.x(UL);
        const lanes<Arch> oy = a.y(UL);
        return lane_verdicts{lane_bits(sat4_steps<lanes<Arch>>::collide(moved(a, ox, oy), moved(b, ox, oy))), 0};
    }
};

}  // namespace
}  // namespace obbsat::detail
