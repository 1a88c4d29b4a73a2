// Method conservative on one pair per lane: the same float operations, in the
// same order, as obbsat::ref::conservative
// (scalar_ref/include/obbsat/ref/conservative.hpp states them and why a claim
// of "apart" is always true). Fused projections leave room for the margin:
// the method costs what sat4 costs.
#pragma once

#include "lanes/fused_multiply_add.hpp"
#include "lanes/lanes.hpp"
#include "lanes/sat4_lanes.hpp"

namespace obbsat::detail {
namespace {

template <class Arch>
struct conservative_lanes {
    static constexpr bool has_slow_path = false;

    using batch = lanes<Arch>;
    using mask = lane_mask<Arch>;

    /// max(|u|, |v|): one VRANGEPS where AVX-512DQ has it, exact either way.
    static OBBSAT_LANE_INLINE batch larger_magnitude(const batch& u, const batch& v) {
#ifdef __AVX512DQ__
        if constexpr (std::is_base_of<xsimd::avx512dq, Arch>::value) {
            return batch(_mm512_range_ps(u, v, 0x0b));  // select the larger |.|, clear the sign
        }
#endif
        return xsimd::max(xsimd::abs(u), xsimd::abs(v));
    }

    /// (K * 2^66) * c: K (1 + 2^-10) 2^-21 per lane, +inf where K >= 2^62.
    static OBBSAT_LANE_INLINE batch margin_scale(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        batch k;
        if constexpr (std::is_base_of<xsimd::avx512dq, Arch>::value) {
            k = larger_magnitude(a.c[0], a.c[1]);
            for (unsigned i = 2; i < coord_count; ++i) {
                k = larger_magnitude(k, a.c[i]);
            }
            for (unsigned i = 0; i < coord_count; ++i) {
                k = larger_magnitude(k, b.c[i]);
            }
        } else {
            // Non-negative floats order as their bit patterns do: the integer
            // maximum of the magnitudes runs beside the float work.
            using bits = xsimd::batch<std::int32_t, Arch>;
            const bits magnitude(0x7fffffff);
            bits largest = xsimd::bitwise_cast<bits>(a.c[0]) & magnitude;
            for (unsigned i = 1; i < coord_count; ++i) {
                largest = xsimd::max(largest, xsimd::bitwise_cast<bits>(a.c[i]) & magnitude);
            }
            for (unsigned i = 0; i < coord_count; ++i) {
                largest = xsimd::max(largest, xsimd::bitwise_cast<bits>(b.c[i]) & magnitude);
            }
            k = xsimd::bitwise_cast<batch>(largest);
        }
        return (k * batch(0x1p66f)) * batch(0x1.004p-87f);
    }

    /// min and max of the four fused corner scalars fma(x, ax, y * ay), folded UL, UR, LR, LL.
    static OBBSAT_LANE_INLINE void project(const quad_lanes<Arch>& q, const batch& ax, const batch& ay, batch& lo,
                                           batch& hi) {
        batch s[4];
        for (unsigned k = 0; k < 4; ++k) {
            s[k] = fused_multiply_add<Arch>(q.x(k), ax, q.y(k) * ay);
        }
        sat4_steps<batch>::fold(s, lo, hi);
    }

    static OBBSAT_LANE_INLINE mask proven_apart_on(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b,
                                                   const batch& ax, const batch& ay, const batch& scale) {
        batch min_a, max_a, min_b, max_b;
        project(a, ax, ay, min_a, max_a);
        project(b, ax, ay, min_b, max_b);
        const batch margin = fused_multiply_add<Arch>(scale, larger_magnitude(ax, ay), batch(0x1p-140f));
        return max_pick(min_b - max_a, min_a - max_b) > margin;
    }

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        const batch scale = margin_scale(a, b);
        const mask apart_on_a = proven_apart_on(a, b, a.x(UR) - a.x(UL), a.y(UR) - a.y(UL), scale) |
                                proven_apart_on(a, b, a.x(UR) - a.x(LR), a.y(UR) - a.y(LR), scale);
        // As in sat4: B's axes cannot change a lane A's axes already decided.
        if (xsimd::all(apart_on_a)) {
            return lane_verdicts{0, 0};
        }
        const mask apart = apart_on_a | proven_apart_on(a, b, b.x(UL) - b.x(LL), b.y(UL) - b.y(LL), scale) |
                           proven_apart_on(a, b, b.x(UL) - b.x(UR), b.y(UL) - b.y(UR), scale);
        return lane_verdicts{lane_bits(~apart), 0};
    }
};

}  // namespace
}  // namespace obbsat::detail
