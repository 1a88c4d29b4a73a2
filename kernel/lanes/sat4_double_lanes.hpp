// Method sat4_double on one pair per lane: the float corners widened exactly
// to double, then sat4's steps in double, as
// scalar_ref/include/obbsat/ref/sat4_double.hpp defines it. A vector of W float
// lanes becomes two vectors of W/2 double lanes (its low and high halves).
#pragma once

#include "lanes/sat4_lanes.hpp"

namespace obbsat::detail {
namespace {

template <class Arch>
struct sat4_double_lanes {
    static constexpr bool has_slow_path = false;
    using wide = xsimd::batch<double, Arch>;
    using reg = typename lanes<Arch>::register_type;
    static constexpr std::size_t half_width = lanes<Arch>::size / 2;

    /// Lanes [0, W/2) (Upper false) or [W/2, W) (Upper true) of v, as doubles.
    template <bool Upper>
    static OBBSAT_LANE_INLINE wide widen(const lanes<Arch>& v) {
        const reg r = v;
        if constexpr (half_width == 8) {
#ifdef __AVX512DQ__
            return _mm512_cvtps_pd(Upper ? _mm512_extractf32x8_ps(r, 1) : _mm512_castps512_ps256(r));
#endif
        } else if constexpr (half_width == 4) {
#ifdef __AVX__
            return _mm256_cvtps_pd(Upper ? _mm256_extractf128_ps(r, 1) : _mm256_castps256_ps128(r));
#endif
        } else {
            return _mm_cvtps_pd(Upper ? _mm_movehl_ps(r, r) : r);
        }
    }

    template <bool Upper>
    static OBBSAT_LANE_INLINE quad<wide> widen(const quad_lanes<Arch>& q) {
        quad<wide> out;
        for (unsigned c = 0; c < coord_count; ++c) {
            out.c[c] = widen<Upper>(q.c[c]);
        }
        return out;
    }

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad_lanes<Arch>& a, const quad_lanes<Arch>& b) {
        const unsigned low = lane_bits(sat4_steps<wide>::collide(widen<false>(a), widen<false>(b)));
        const unsigned high = lane_bits(sat4_steps<wide>::collide(widen<true>(a), widen<true>(b)));
        return lane_verdicts{low | (high << half_width), 0};
    }
};

}  // namespace
}  // namespace obbsat::detail
