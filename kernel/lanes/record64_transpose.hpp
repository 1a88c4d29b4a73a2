// Loading one vector of double-corner rectangles from their 64-byte records
// (rect_records64: ulx, uly, urx, ury, lrx, lry, llx, lly): each lane's record
// is read whole and the records are transposed in registers into the eight
// coordinate vectors, lane i holding the rectangle pick(i) names.
//
// A vector holds W doubles (2 for SSE2, 4 for AVX2, 8 for AVX-512) and a
// record is 8 / W registers, so the load is W x W transposes of doubles:
//   SSE2     one 2x2 per 16-byte quarter of the record: unpack low and high;
//   AVX2     one 4x4 per 32-byte half: unpack within 128-bit blocks, then
//            regroup the blocks (vperm2f128);
//   AVX-512  one 8x8 of the whole records: unpack, then two rounds of
//            128-bit block shuffles (vshuff64x2).
// Each translation unit is compiled for one ISA, so the branches for wider
// ones are compiled out with the ISA's own predefined macros.
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/rect64.hpp>

#include <cstddef>

namespace obbsat::detail {
namespace {

template <class Arch>
struct record64_transpose {
    using batch = xsimd::batch<double, Arch>;
    static constexpr std::size_t width = batch::size;

    /// The rectangles pick(0) .. pick(width - 1) (each a const rect64*) as
    /// eight coordinate vectors, lane i from pick(i).
    template <class Pick>
    static OBBSAT_LANE_INLINE quad<batch> load(const Pick& pick) {
        auto record = [&](std::size_t lane) { return reinterpret_cast<const double*>(pick(lane)); };
        quad<batch> q;
        if constexpr (width == 8) {
#ifdef __AVX512F__
            // u[2j], u[2j + 1]: coordinates (0, 2, 4, 6) and (1, 3, 5, 7) of
            // records 2j and 2j + 1, interleaved per 128-bit block.
            __m512d u[8];
            for (std::size_t j = 0; j < 4; ++j) {
                const __m512d first = _mm512_loadu_pd(record(2 * j));
                const __m512d second = _mm512_loadu_pd(record(2 * j + 1));
                u[2 * j] = _mm512_unpacklo_pd(first, second);
                u[2 * j + 1] = _mm512_unpackhi_pd(first, second);
            }
            // v[h][p]: blocks of records 0..3 (h = 0) or 4..7 (h = 1) holding
            // coordinates (0, 4), (2, 6), (1, 5), (3, 7) for p = 0, 1, 2, 3.
            __m512d v[2][4];
            for (std::size_t h = 0; h < 2; ++h) {
                const __m512d* w = u + 4 * h;
                v[h][0] = _mm512_shuffle_f64x2(w[0], w[2], 0x88);
                v[h][1] = _mm512_shuffle_f64x2(w[0], w[2], 0xdd);
                v[h][2] = _mm512_shuffle_f64x2(w[1], w[3], 0x88);
                v[h][3] = _mm512_shuffle_f64x2(w[1], w[3], 0xdd);
            }
            constexpr unsigned low_coordinate[4] = {0, 2, 1, 3};
            for (std::size_t p = 0; p < 4; ++p) {
                q.c[low_coordinate[p]] = batch(_mm512_shuffle_f64x2(v[0][p], v[1][p], 0x88));
                q.c[low_coordinate[p] + 4] = batch(_mm512_shuffle_f64x2(v[0][p], v[1][p], 0xdd));
            }
#endif
        } else if constexpr (width == 4) {
#ifdef __AVX__
            for (std::size_t half = 0; half < 2; ++half) {
                __m256d r[4];
                for (std::size_t k = 0; k < 4; ++k) {
                    r[k] = _mm256_loadu_pd(record(k) + 4 * half);
                }
                // Coordinates (0, 2) and (1, 3) of two records per 128-bit block.
                const __m256d even01 = _mm256_unpacklo_pd(r[0], r[1]);
                const __m256d odd01 = _mm256_unpackhi_pd(r[0], r[1]);
                const __m256d even23 = _mm256_unpacklo_pd(r[2], r[3]);
                const __m256d odd23 = _mm256_unpackhi_pd(r[2], r[3]);
                q.c[4 * half + 0] = batch(_mm256_permute2f128_pd(even01, even23, 0x20));
                q.c[4 * half + 1] = batch(_mm256_permute2f128_pd(odd01, odd23, 0x20));
                q.c[4 * half + 2] = batch(_mm256_permute2f128_pd(even01, even23, 0x31));
                q.c[4 * half + 3] = batch(_mm256_permute2f128_pd(odd01, odd23, 0x31));
            }
#endif
        } else {
            for (std::size_t quarter = 0; quarter < 4; ++quarter) {
                const __m128d first = _mm_loadu_pd(record(0) + 2 * quarter);
                const __m128d second = _mm_loadu_pd(record(1) + 2 * quarter);
                q.c[2 * quarter] = batch(_mm_unpacklo_pd(first, second));
                q.c[2 * quarter + 1] = batch(_mm_unpackhi_pd(first, second));
            }
        }
        return q;
    }
};

}  // namespace
}  // namespace obbsat::detail
