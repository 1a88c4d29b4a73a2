// x * y + z rounded once, per lane, for every backend: the operation the
// scalar reference writes as std::fma. AVX-512F and the AVX2 backend (built
// with FMA3, which every AVX2 CPU the dispatcher accepts has) have it as one
// instruction. SSE2 has none, so there it is computed exactly in double:
// the product of two floats is exact in double, the sum is rounded to odd
// (an inexact result gets an odd last bit), and a value rounded to odd with
// 53 bits rounds to the same float as the exact sum, because 53 >= 24 + 2.
#pragma once

#include "lanes/lanes.hpp"

#include <cmath>

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

/// The lanes of a double sum whose conversion to float could differ from the
/// once-rounded result: an exact float midpoint (the 29 bits below float
/// precision are 1000...0) or a nonzero value in the float subnormal range.
inline int double_rounding_risk(__m128d sum) {
    const __m128i bits = _mm_castpd_si128(sum);
    const __m128i below_float = _mm_and_si128(bits, _mm_set_epi32(0, 0x1fffffff, 0, 0x1fffffff));
    const __m128i midpoint = _mm_cmpeq_epi32(below_float, _mm_set_epi32(0, 0x10000000, 0, 0x10000000));
    const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), sum);
    const __m128d subnormal = _mm_and_pd(_mm_cmplt_pd(magnitude, _mm_set1_pd(0x1p-126)),
                                         _mm_cmpgt_pd(magnitude, _mm_setzero_pd()));
    // A midpoint needs the low 32 bits to match as well as the high ones: lane
    // k's low dword is element 2k, and the high dword's 3 bits are in 2k + 1.
    const int midpoint_dwords = _mm_movemask_ps(_mm_castsi128_ps(midpoint));
    return (midpoint_dwords & 0x5) | _mm_movemask_pd(subnormal);
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
        const __m128d x_low = _mm_cvtps_pd(xf), y_low = _mm_cvtps_pd(yf), z_low = _mm_cvtps_pd(zf);
        const __m128d x_high = _mm_cvtps_pd(_mm_movehl_ps(xf, xf));
        const __m128d y_high = _mm_cvtps_pd(_mm_movehl_ps(yf, yf));
        const __m128d z_high = _mm_cvtps_pd(_mm_movehl_ps(zf, zf));
        __m128d low = _mm_add_pd(_mm_mul_pd(x_low, y_low), z_low);
        __m128d high = _mm_add_pd(_mm_mul_pd(x_high, y_high), z_high);
        // Rounding the double sum to float is already the once-rounded result
        // unless that sum sits on a float midpoint or below the normal range;
        // only then is the sum redone rounded to odd.
        if ((double_rounding_risk(low) | double_rounding_risk(high)) != 0) {
            low = multiply_add_rounded_to_odd(x_low, y_low, z_low);
            high = multiply_add_rounded_to_odd(x_high, y_high, z_high);
        }
        return lanes<Arch>(_mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high)));
    }
}

/// The same on double lanes, the operation std::fma does on one double. SSE2
/// has neither the instruction nor a wider type to compute it exactly in, so
/// there each lane goes through std::fma itself (a call into the C library,
/// compiled at the baseline): correct, not fast.
template <class Arch>
xsimd::batch<double, Arch> fused_multiply_add(const xsimd::batch<double, Arch>& x,
                                              const xsimd::batch<double, Arch>& y,
                                              const xsimd::batch<double, Arch>& z) {
    using batch = xsimd::batch<double, Arch>;
    if constexpr (std::is_base_of<xsimd::avx512f, Arch>::value) {
#ifdef __AVX512F__
        return batch(_mm512_fmadd_pd(x, y, z));
#endif
    } else if constexpr (std::is_base_of<xsimd::avx, Arch>::value) {
#ifdef __FMA__
        return batch(_mm256_fmadd_pd(x, y, z));
#else
        static_assert(sizeof(Arch) == 0, "the AVX2 backend must be compiled with -mfma");
#endif
    } else {
        const __m128d xd = x, yd = y, zd = z;
        const double low = std::fma(_mm_cvtsd_f64(xd), _mm_cvtsd_f64(yd), _mm_cvtsd_f64(zd));
        const double high = std::fma(_mm_cvtsd_f64(_mm_unpackhi_pd(xd, xd)), _mm_cvtsd_f64(_mm_unpackhi_pd(yd, yd)),
                                     _mm_cvtsd_f64(_mm_unpackhi_pd(zd, zd)));
        return batch(_mm_set_pd(high, low));
    }
}

}  // namespace
}  // namespace obbsat::detail
