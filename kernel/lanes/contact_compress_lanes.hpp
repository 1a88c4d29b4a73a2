// Compressing the lanes of a mask to the front of a vector and storing it
// whole, for the contact batch driver's list of the places of the pairs
// within the margin and what the first pass chose for them
// (contact_batch.hpp). AVX-512 has compress instructions; AVX2 permutes by
// the mask's set lanes read from a table; SSE2 has neither (compresses
// false). A compressed store writes a
// whole vector: the lanes past the set ones are zero (AVX-512) or copies of
// other lanes (AVX2), always written. Private to each per-ISA object
// (README.md).
#pragma once

#include "lanes/lanes.hpp"


#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace obbsat::detail {
namespace {

/// Whether this ISA compresses lanes (AVX-512, AVX2).
template <class Arch>
constexpr bool compresses_lanes() {
#if defined(__AVX512F__) || defined(__AVX2__)
    return !std::is_same<Arch, xsimd::sse2>::value;
#else
    return false;
#endif
}

#if defined(__AVX2__) && !defined(__AVX512F__)
/// For each mask of eight lanes, the set lanes in order, one per nibble
/// (nibble k: the k-th set lane); for 64-bit lanes (masks of four) each set
/// lane L as the two 32-bit halves 2L, 2L + 1.
struct set_lane_table {
    std::uint32_t of32[256];
    std::uint32_t of64[16];
};

constexpr set_lane_table make_set_lane_table() {
    set_lane_table t{};
    for (unsigned m = 0; m < 256; ++m) {
        unsigned k = 0;
        for (unsigned lane = 0; lane < 8; ++lane) {
            if (((m >> lane) & 1u) != 0) {
                t.of32[m] |= lane << (4 * k++);
            }
        }
    }
    for (unsigned m = 0; m < 16; ++m) {
        unsigned k = 0;
        for (unsigned lane = 0; lane < 4; ++lane) {
            if (((m >> lane) & 1u) != 0) {
                t.of64[m] |= ((2 * lane) << (4 * k)) | ((2 * lane + 1) << (4 * (k + 1)));
                k += 2;
            }
        }
    }
    return t;
}

constexpr set_lane_table set_lanes = make_set_lane_table();

/// The permutation that brings the lanes of a packed nibble list to the front.
inline __m256i permutation_of(std::uint32_t packed) {
    return _mm256_srlv_epi32(_mm256_set1_epi32(static_cast<int>(packed)),
                             _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28));
}
#endif

/// Stores the lanes of `v` set in `bits`, in lane order, from out[0]: a whole vector.
template <class Arch, class Real>
OBBSAT_LANE_INLINE void store_compressed(unsigned bits, const xsimd::batch<Real, Arch>& v, Real* out) {
#if defined(__AVX512F__)
    if constexpr (std::is_same<Real, float>::value) {
        _mm512_storeu_ps(out, _mm512_maskz_compress_ps(static_cast<__mmask16>(bits), v));
    } else {
        _mm512_storeu_pd(out, _mm512_maskz_compress_pd(static_cast<__mmask8>(bits), v));
    }
#elif defined(__AVX2__)
    if constexpr (std::is_same<Real, float>::value) {
        _mm256_storeu_ps(out, _mm256_permutevar8x32_ps(v, permutation_of(set_lanes.of32[bits & 0xffu])));
    } else {
        const __m256 halves = _mm256_castpd_ps(v);
        _mm256_storeu_pd(out, _mm256_castps_pd(_mm256_permutevar8x32_ps(halves, permutation_of(set_lanes.of64[bits & 0xfu]))));
    }
#else
    (void)bits, (void)v, (void)out;
#endif
}

/// Stores first + lane for each lane set in `bits` (of at most 16), in lane
/// order, from out[0]; writes 16 places (AVX-512) or 8 (AVX2).
template <class Arch>
OBBSAT_LANE_INLINE void store_compressed_places(unsigned bits, std::uint32_t first, std::uint32_t* out) {
#if defined(__AVX512F__)
    const __m512i places = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(first)),
                                            _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
    _mm512_storeu_si512(out, _mm512_maskz_compress_epi32(static_cast<__mmask16>(bits), places));
#elif defined(__AVX2__)
    const __m256i places = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(first)),
                                            _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out),
                        _mm256_permutevar8x32_epi32(places, permutation_of(set_lanes.of32[bits & 0xffu])));
#else
    (void)bits, (void)first, (void)out;
#endif
}

}  // namespace
}  // namespace obbsat::detail
