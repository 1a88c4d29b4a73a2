// Loading one vector of double poses from 64-byte pose_records64 records
// (cx, cy, hx, hy, c, s, 0, 0): each lane's record is read in wide pieces and
// the pieces are transposed in registers into the six field vectors of
// pose64_lanes, lane i from record pick(i). Staging the records through memory
// instead (one store per double, one vector load per field) stalled every load
// on the stores it had to forward from.
//
// Every ISA pairs fields two by two (cx with cy, hx with hy, c with s): a
// 128-bit block holding one record's two fields of a pair, unpacked against
// the block of the next record, gives those two records' values of both
// fields. The ISAs differ only in how the blocks of several records are put
// side by side:
//   SSE2    2 records: one 128-bit load per pair of fields and record.
//   AVX2    4 records: blocks of records k and k + 2 joined by an insert.
//   AVX-512 8 records: the first halves (cx, cy, hx, hy) of records k and
//           k + 2 joined by an insert, the second halves (c, s, 0, 0) by a
//           masked load of record k + 2's own cache line (no shuffle); the
//           unpacked blocks are then regrouped across the register.
// Each translation unit is compiled for one ISA, so the branches for wider
// ones are compiled out with the ISA's own predefined macros.
#pragma once

#include "lanes/lanes.hpp"

#include <cstddef>

namespace obbsat::detail {
namespace {

template <class Arch>
using lanes64 = xsimd::batch<double, Arch>;

template <class Arch>
using lane_mask64 = xsimd::batch_bool<double, Arch>;

/// One double pose per lane.
template <class Arch>
struct pose64_lanes {
    lanes64<Arch> cx, cy, hx, hy, c, s;
};

template <class Arch>
struct pose64_record_transpose {
    using batch = lanes64<Arch>;
    static constexpr std::size_t width = batch::size;

    /// The six fields, `pair_at(offset, x, y)` setting x and y to the fields at
    /// `offset` and `offset + 1` of every lane's record.
    template <class PairAt>
    static OBBSAT_LANE_INLINE pose64_lanes<Arch> by_field_pairs(const PairAt& pair_at) {
        pose64_lanes<Arch> p;
        pair_at(0, p.cx, p.cy);
        pair_at(2, p.hx, p.hy);
        pair_at(4, p.c, p.s);
        return p;
    }

    /// The poses of records pick(0) .. pick(width - 1) (each a const double*
    /// to a 64-byte record), lane i from pick(i).
    template <class Pick>
    static OBBSAT_LANE_INLINE pose64_lanes<Arch> load(const Pick& pick) {
        if constexpr (width == 8) {
#ifdef __AVX512F__
            // first[k]: (cx cy hx hy) of records r and r + 2, r = 4 * (k / 2) + k % 2, and second[k]
            // their (c s 0 0): registers 0..3 hold records (0, 2), (1, 3), (4, 6), (5, 7).
            __m512d first[4], second[4];
            for (std::size_t k = 0; k < 4; ++k) {
                const std::size_t r = 4 * (k / 2) + k % 2;
                const __m512d low = _mm512_castpd256_pd512(_mm256_loadu_pd(pick(r)));
                first[k] = _mm512_insertf64x4(low, _mm256_loadu_pd(pick(r + 2)), 1);
                // The masked load reads only record r + 2's second half, in its own 64-byte line.
                const __m512d c_s = _mm512_castpd256_pd512(_mm256_loadu_pd(pick(r) + 4));
                second[k] = _mm512_mask_loadu_pd(c_s, 0xf0, pick(r + 2));
            }
            // Unpacked, block j of an even/odd register pair holds records (0 1)(0 1)(2 3)(2 3),
            // resp. (4 5)(4 5)(6 7)(6 7); blocks 0 and 2 of the first, then of the second, are
            // records 0..7 in order (0x88), blocks 1 and 3 the second field of the half (0xdd).
            const __m512d x_lo = _mm512_unpacklo_pd(first[0], first[1]);
            const __m512d x_hi = _mm512_unpacklo_pd(first[2], first[3]);
            const __m512d y_lo = _mm512_unpackhi_pd(first[0], first[1]);
            const __m512d y_hi = _mm512_unpackhi_pd(first[2], first[3]);
            const __m512d c_lo = _mm512_unpacklo_pd(second[0], second[1]);
            const __m512d c_hi = _mm512_unpacklo_pd(second[2], second[3]);
            const __m512d s_lo = _mm512_unpackhi_pd(second[0], second[1]);
            const __m512d s_hi = _mm512_unpackhi_pd(second[2], second[3]);
            return pose64_lanes<Arch>{batch(_mm512_shuffle_f64x2(x_lo, x_hi, 0x88)),
                                      batch(_mm512_shuffle_f64x2(y_lo, y_hi, 0x88)),
                                      batch(_mm512_shuffle_f64x2(x_lo, x_hi, 0xdd)),
                                      batch(_mm512_shuffle_f64x2(y_lo, y_hi, 0xdd)),
                                      batch(_mm512_shuffle_f64x2(c_lo, c_hi, 0x88)),
                                      batch(_mm512_shuffle_f64x2(s_lo, s_hi, 0x88))};
#endif
        } else if constexpr (width == 4) {
#ifdef __AVX__
            // Per pair of fields at `offset`: blocks of records (0, 2) and (1, 3).
            return by_field_pairs([&](std::size_t offset, batch& x, batch& y) __attribute__((always_inline)) {
                const __m256d even = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(pick(0) + offset)),
                                                          _mm_loadu_pd(pick(2) + offset), 1);
                const __m256d odd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(pick(1) + offset)),
                                                         _mm_loadu_pd(pick(3) + offset), 1);
                x = _mm256_unpacklo_pd(even, odd);
                y = _mm256_unpackhi_pd(even, odd);
            });
#endif
        } else {
            return by_field_pairs([&](std::size_t offset, batch& x, batch& y) __attribute__((always_inline)) {
                const __m128d first = _mm_loadu_pd(pick(0) + offset);
                const __m128d second = _mm_loadu_pd(pick(1) + offset);
                x = _mm_unpacklo_pd(first, second);
                y = _mm_unpackhi_pd(first, second);
            });
        }
    }
};

}  // namespace
}  // namespace obbsat::detail
