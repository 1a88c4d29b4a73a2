// x * y + z rounded once, per lane, for every backend: the operation the
// scalar reference writes as std::fma. AVX-512F and the AVX2 backend (built
// with FMA3, which every AVX2 CPU the dispatcher accepts has) have it as one
// instruction. SSE2 has none, so there it is computed exactly in double:
// the product of two floats is exact in double, the sum is rounded to odd
// (an inexact result gets an odd last bit), and a value rounded to odd with
// 53 bits rounds to the same float as the exact sum, because 53 >= 24 + 2.
#pragma once

#include "lanes.hpp"

namespace obbsat::detail {
namespace {

/// Two doubles per lane, each x * y + z rounded to odd (finite inputs; an
/// infinite or NaN sum is left as the double arithmetic gives it).
inline __m128d multiply_add_rounded_to_odd(__m128d x, __m128d y, __m128d z) {
    const __m128d product = _mm_mul_pd(x, y);  // exact: 24 + 24 bits
    const __m128d sum = _mm_add_pd(product, z);
    // Knuth's two-sum: the exact error of the rounded sum.
    const __m128d z_part = _mm_sub_pd(sum, product);
    const __m128d error = _mm_add_pd(_mm_sub_pd(product, _mm_sub_pd(sum, z_part)), _mm_sub_pd(z, z_part));
    const __m128d zero = _mm_setzero_pd();
    const __m128i inexact = _mm_castpd_si128(_mm_or_pd(_mm_cmplt_pd(error, zero), _mm_cmpgt_pd(error, zero)));

    const __m128i sum_bits = _mm_castpd_si128(sum);
    const __m128i one = _mm_set_epi32(0, 1, 0, 1);
    // Last bit clear, as one 64-bit mask per lane (SSE2 compares 32 bits).
    const __m128i even_low = _mm_cmpeq_epi32(_mm_and_si128(sum_bits, one), _mm_setzero_si128());
    const __m128i even = _mm_shuffle_epi32(even_low, _MM_SHUFFLE(2, 2, 0, 0));
    // Toward the exact value: +1 in the bit pattern when the error has the
    // sum's sign (away from zero), -1 otherwise.
    const __m128i signs_differ_high = _mm_srai_epi32(_mm_xor_si128(sum_bits, _mm_castpd_si128(error)), 31);
    const __m128i signs_differ = _mm_shuffle_epi32(signs_differ_high, _MM_SHUFFLE(3, 3, 1, 1));
    const __m128i step = _mm_and_si128(_mm_and_si128(inexact, even), _mm_or_si128(signs_differ, one));
    return _mm_castsi128_pd(_mm_add_epi64(sum_bits, step));
}

template <class Arch>
lanes<Arch> fused_multiply_add(const lanes<Arch>& x, const lanes<Arch>& y, const lanes<Arch>& z) {
    if constexpr (std::is_base_of<xsimd::avx512f, Arch>::value) {
#ifdef __AVX512F__
        return lanes<Arch>(_mm512_fmadd_ps(x, y, z));
#endif
    } else if constexpr (std::is_base_of<xsimd::avx, Arch>::value) {
#ifdef __FMA__
        return lanes<Arch>(_mm256_fmadd_ps(x, y, z));
#else
        static_assert(sizeof(Arch) == 0, "the AVX2 backend must be compiled with -mfma");
#endif
    } else {
        const __m128 xf = x, yf = y, zf = z;
        const __m128d low = multiply_add_rounded_to_odd(_mm_cvtps_pd(xf), _mm_cvtps_pd(yf), _mm_cvtps_pd(zf));
        const __m128d high = multiply_add_rounded_to_odd(
            _mm_cvtps_pd(_mm_movehl_ps(xf, xf)), _mm_cvtps_pd(_mm_movehl_ps(yf, yf)), _mm_cvtps_pd(_mm_movehl_ps(zf, zf)));
        return lanes<Arch>(_mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high)));
    }
}

}  // namespace
}  // namespace obbsat::detail
