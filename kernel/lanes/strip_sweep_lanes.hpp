// The sweep of one strip (strip_view.hpp), written once over the xsimd
// architecture: entry e against a vector of later entries at a time, all
// bounds compared in one pass, candidates written in entry order. Internal
// linkage, as every lane header compiled into the per-ISA units.
#pragma once

#include "lanes/lanes.hpp"
#include "dispatch/strip_view.hpp"

#include <xsimd/xsimd.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// Writes (e_id, ids[j]) for every lane j set in `bits`, in lane order, to
/// out[0, k) and returns k; may write garbage up to out[width). AVX-512
/// compresses the pairs in registers; narrower vectors write every lane and
/// advance by the lane's bit, without a branch.
template <class Arch>
OBBSAT_LANE_INLINE std::size_t emit_candidates(unsigned bits, std::int32_t e_id, const std::int32_t* ids,
                                               pair_index* out) {
    constexpr std::size_t width = xsimd::batch<float, Arch>::size;
#ifdef __AVX512F__
    if constexpr (std::is_base_of<xsimd::avx512f, Arch>::value) {
        static_assert(width == 16 && sizeof(pair_index) == 8, "two vectors of eight 64-bit pairs");
        // A pair is one 64-bit word: a in the low half, b in the high half.
        const __m512i id_lanes = _mm512_loadu_si512(ids);
        const __m512i a = _mm512_set1_epi64(static_cast<long long>(static_cast<std::uint32_t>(e_id)));
        const __m512i low = _mm512_or_si512(
            _mm512_slli_epi64(_mm512_cvtepu32_epi64(_mm512_castsi512_si256(id_lanes)), 32), a);
        const __m512i high = _mm512_or_si512(
            _mm512_slli_epi64(_mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64(id_lanes, 1)), 32), a);
        const auto low_bits = static_cast<__mmask8>(bits & 0xffu);
        const auto high_bits = static_cast<__mmask8>(bits >> 8);
        _mm512_storeu_si512(out, _mm512_maskz_compress_epi64(low_bits, low));
        const auto low_count = static_cast<std::size_t>(__builtin_popcount(bits & 0xffu));
        _mm512_storeu_si512(out + low_count, _mm512_maskz_compress_epi64(high_bits, high));
        return low_count + static_cast<std::size_t>(__builtin_popcount(bits >> 8));
    }
#endif
    std::size_t count = 0;
    for (std::size_t j = 0; j < width; ++j) {
        out[count].a = static_cast<std::uint32_t>(e_id);
        out[count].b = static_cast<std::uint32_t>(ids[j]);
        count += (bits >> j) & 1u;
    }
    return count;
}

/// The sweep for queries within one store (Cross false) or across two.
/// Lanes past the reach of e need no test of their own: q is monotone, so a
/// lane whose lo_x is at most e's hi_x is within reach. The sentinels' starts
/// (-1) fails the starts test of every entry, even one whose bounds are
/// infinite and so overlap the sentinels' too.
template <class Arch, bool Cross>
std::size_t strip_sweep_of(const strip_view& strip, sweep_cursor& cursor, pair_index* out, std::size_t capacity) {
    using floats = xsimd::batch<float, Arch>;
    constexpr std::size_t width = floats::size;
    static_assert(width <= strip_padding, "a vector never reads past the sentinels");
    // The arrays held apart from `strip`: a candidate written to `out` might
    // otherwise, for all the compiler knows, change them, and they would be
    // read again from the view after every store.
    const float* const q_lo = strip.q_lo;
    const float* const q_hi = strip.q_hi;
    const std::int32_t* const ids = strip.id;
    const float* const starts = strip.starts;
    const float* const store = strip.store;
    const float* const lo_x = strip.lo_x;
    const float* const lo_y = strip.lo_y;
    const float* const hi_x = strip.hi_x;
    const float* const hi_y = strip.hi_y;
    const std::size_t m = strip.size;
    std::size_t count = 0;
    std::size_t e = cursor.e;
    std::size_t f = cursor.f;
    for (; e + 1 < m; ++e, f = e + 1) {
        const float e_q_hi = q_hi[e];
        const floats e_lo_x(lo_x[e]);
        const floats e_hi_x(hi_x[e]);
        const floats e_lo_y(lo_y[e]);
        const floats e_hi_y(hi_y[e]);
        // Not two visitors: a visitor e needs an f that starts here.
        const floats starts_needed(starts[e] > 0.0f ? 0.0f : 1.0f);
        const floats e_store(store[e]);
        const std::int32_t e_id = ids[e];
        for (;;) {
            if (capacity - count < width) {
                cursor = sweep_cursor{e, f};
                return count;
            }
            auto take = (floats::load_unaligned(lo_x + f) <= e_hi_x) &
                        (floats::load_unaligned(hi_x + f) >= e_lo_x) &
                        (floats::load_unaligned(lo_y + f) <= e_hi_y) &
                        (floats::load_unaligned(hi_y + f) >= e_lo_y) &
                        (floats::load_unaligned(starts + f) >= starts_needed);
            if constexpr (Cross) {
                take = take & (floats::load_unaligned(store + f) != e_store);
            }
            count += emit_candidates<Arch>(lane_bits(take), e_id, ids + f, out + count);
            f += width;
            // q_lo ascends: once the last lane is out of reach, so is the rest.
            if (!(q_lo[f - 1] <= e_q_hi)) {
                break;
            }
        }
    }
    cursor = sweep_cursor{m, m + 1};
    return count;
}

template <class Arch>
std::size_t strip_sweep_lanes(const strip_view& strip, sweep_cursor& cursor, pair_index* out, std::size_t capacity) {
    return strip.cross ? strip_sweep_of<Arch, true>(strip, cursor, out, capacity)
                       : strip_sweep_of<Arch, false>(strip, cursor, out, capacity);
}

}  // namespace
}  // namespace obbsat::detail
