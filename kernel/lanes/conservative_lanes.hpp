// Method conservative on one pair per lane: the same float operations, in the
// same order, as obbsat::ref::conservative
// (scalar_ref/include/obbsat/ref/conservative.hpp states them and why a claim
// of "apart" is always true), or on double corners the double operations of
// obbsat/ref/conservative64.hpp (Real = double: only the scale's constants,
// the margin's floor and how the largest magnitude is found differ). Fused
// projections leave room for the margin: the method costs what sat4 costs.
#pragma once

#include "lanes/fused_multiply_add.hpp"
#include "lanes/lanes.hpp"
#include "lanes/sat4_lanes.hpp"

namespace obbsat::detail {
namespace {

/// The constants of one precision, those of the scalar reference.
template <class Real>
struct conservative_constants;

template <>
struct conservative_constants<float> {
    static constexpr float guard = 0x1p66f;         // K · guard overflows from K = 2^62 on
    static constexpr float scale = 0x1.004p-87f;    // then (K · guard) · scale = 2^-21 K (1 + 2^-10)
    static constexpr float margin_floor = 0x1p-140f;
};

template <>
struct conservative_constants<double> {
    static constexpr double guard = 0x1p513;        // K · guard overflows from K = 2^511 on
    static constexpr double scale = 0x1.004p-563;   // then (K · guard) · scale = 2^-50 K (1 + 2^-10)
    static constexpr double margin_floor = 0x1p-1000;
};

/// The method's steps on corners of type Real, one pair per lane.
template <class Arch, class Real>
struct conservative_steps {
    static constexpr bool has_slow_path = false;

    using batch = xsimd::batch<Real, Arch>;
    using mask = xsimd::batch_bool<Real, Arch>;
    using corners = quad<batch>;
    using constants = conservative_constants<Real>;
    static constexpr bool is_float = std::is_same<Real, float>::value;

    /// max(|u|, |v|): one VRANGEPS where AVX-512DQ has it, exact either way.
    static OBBSAT_LANE_INLINE batch larger_magnitude(const batch& u, const batch& v) {
#ifdef __AVX512DQ__
        if constexpr (is_float && std::is_base_of<xsimd::avx512dq, Arch>::value) {
            return batch(_mm512_range_ps(u, v, 0x0b));  // select the larger |.|, clear the sign
        }
#endif
        return xsimd::max(xsimd::abs(u), xsimd::abs(v));
    }

    /// (K * guard) * scale: K (1 + 2^-10) 2^-21 (float) or 2^-50 (double) per
    /// lane, +inf where K · guard overflows.
    static OBBSAT_LANE_INLINE batch margin_scale(const corners& a, const corners& b) {
        batch k;
        // The magnitudes are finite and none is negative, so their largest,
        // found in any order, is the reference's max-pick fold.
        if constexpr (!is_float || std::is_base_of<xsimd::avx512dq, Arch>::value) {
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
        return (k * batch(constants::guard)) * batch(constants::scale);
    }

    /// min and max of the four fused corner scalars fma(x, ax, y * ay), folded UL, UR, LR, LL.
    static OBBSAT_LANE_INLINE void project(const corners& q, const batch& ax, const batch& ay, batch& lo,
                                           batch& hi) {
        batch s[4];
        for (unsigned k = 0; k < 4; ++k) {
            s[k] = fused_multiply_add<Arch>(q.x(k), ax, q.y(k) * ay);
        }
        sat4_steps<batch>::fold(s, lo, hi);
    }

    static OBBSAT_LANE_INLINE mask proven_apart_on(const corners& a, const corners& b,
                                                   const batch& ax, const batch& ay, const batch& scale) {
        batch min_a, max_a, min_b, max_b;
        project(a, ax, ay, min_a, max_a);
        project(b, ax, ay, min_b, max_b);
        const batch margin = fused_multiply_add<Arch>(scale, larger_magnitude(ax, ay), batch(constants::margin_floor));
        return max_pick(min_b - max_a, min_a - max_b) > margin;
    }

    static OBBSAT_LANE_INLINE lane_verdicts collide(const corners& a, const corners& b) {
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

/// Method conservative on float corners (the lanes method_catalogue.hpp names).
template <class Arch>
struct conservative_lanes : conservative_steps<Arch, float> {};

}  // namespace
}  // namespace obbsat::detail
