// Loading one vector of rectangles from packed 32-byte records: each lane's
// record is read whole and the records are transposed in registers into the
// eight coordinate vectors of quad_lanes.
//
// A record is two 128-bit halves: (ulx, uly, urx, ury) and (lrx, lry, llx, lly).
// For a vector of 4·L lanes (L 128-bit blocks: 1 for SSE2, 2 for AVX2, 4 for
// AVX-512), register k (k < 4) is assembled so that its block j holds a half of
// record k + 4j; a 4x4 transpose inside every 128-bit block then leaves
// coordinate c of record 4j + k in lane 4j + k, the natural order. Unpack and
// 64-bit shuffles never cross 128-bit blocks, so the transpose is the same
// three-instruction-kind recipe on every ISA; only the assembly differs.
// Each translation unit is compiled for one ISA, so the branches for wider
// ones are compiled out with the ISA's own predefined macros.
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/rect.hpp>

#include <type_traits>
#include <utility>

namespace obbsat::detail {
namespace {

template <class Arch>
struct record_transpose {
    using reg = typename lanes<Arch>::register_type;
    static constexpr std::size_t width = lanes<Arch>::size;

    static reg unpack_lo(reg a, reg b) {
        if constexpr (width == 16) {
#ifdef __AVX512F__
            return _mm512_unpacklo_ps(a, b);
#endif
        } else if constexpr (width == 8) {
#ifdef __AVX__
            return _mm256_unpacklo_ps(a, b);
#endif
        } else {
            return _mm_unpacklo_ps(a, b);
        }
    }
    static reg unpack_hi(reg a, reg b) {
        if constexpr (width == 16) {
#ifdef __AVX512F__
            return _mm512_unpackhi_ps(a, b);
#endif
        } else if constexpr (width == 8) {
#ifdef __AVX__
            return _mm256_unpackhi_ps(a, b);
#endif
        } else {
            return _mm_unpackhi_ps(a, b);
        }
    }
    /// Per 128-bit block: (a0, a1, b0, b1) for Imm = 0x44, (a2, a3, b2, b3) for Imm = 0xee.
    template <int Imm>
    static reg shuffle(reg a, reg b) {
        if constexpr (width == 16) {
#ifdef __AVX512F__
            return _mm512_shuffle_ps(a, b, Imm);
#endif
        } else if constexpr (width == 8) {
#ifdef __AVX__
            return _mm256_shuffle_ps(a, b, Imm);
#endif
        } else {
            return _mm_shuffle_ps(a, b, Imm);
        }
    }

    /// Writes the four coordinates held by registers r[0..3] into out[0..3].
    static void transpose4(const reg r[4], lanes<Arch> out[4]) {
        const reg t0 = unpack_lo(r[0], r[1]);
        const reg t1 = unpack_hi(r[0], r[1]);
        const reg t2 = unpack_lo(r[2], r[3]);
        const reg t3 = unpack_hi(r[2], r[3]);
        out[0] = shuffle<0x44>(t0, t2);
        out[1] = shuffle<0xee>(t0, t2);
        out[2] = shuffle<0x44>(t1, t3);
        out[3] = shuffle<0xee>(t1, t3);
    }

    /// Registers lo[k], hi[k] with block j holding the halves of record k + 4j,
    /// where record i is `pick(i)` (a const rect*). With `InCache` (records
    /// the caches hold) AVX-512 puts a second record in the upper half of a
    /// register by a masked load of the 64 bytes that end with it, which
    /// takes a load port instead of a shuffle (8% faster in cache); the
    /// masked-off half may lie in the line before the record, or before the
    /// store (masked lanes never fault), which costs a second line from
    /// memory, so records read from memory are inserted instead.
    template <bool InCache, class Pick>
    static void assemble(const Pick& pick, reg lo[4], reg hi[4]) {
        auto half = [&](std::size_t record, unsigned which) {
            return reinterpret_cast<const float*>(pick(record)) + 4 * which;
        };
        for (std::size_t k = 0; k < 4; ++k) {
            if constexpr (width == 16) {
#ifdef __AVX512DQ__
                // Two whole records per register, then 128-bit blocks regrouped:
                // a = [k | k+4], b = [k+8 | k+12] -> lo = (k.lo, k+4.lo, k+8.lo, k+12.lo).
                const auto pair_of = [&](std::size_t first, std::size_t second) {
                    const __m512 low = _mm512_castps256_ps512(_mm256_loadu_ps(half(first, 0)));
                    if constexpr (InCache) {
                        return _mm512_mask_loadu_ps(low, 0xff00, half(second, 0) - 8);
                    } else {
                        return _mm512_insertf32x8(low, _mm256_loadu_ps(half(second, 0)), 1);
                    }
                };
                const __m512 a = pair_of(k, k + 4);
                const __m512 b = pair_of(k + 8, k + 12);
                lo[k] = _mm512_shuffle_f32x4(a, b, 0x88);  // blocks a0, a2, b0, b2
                hi[k] = _mm512_shuffle_f32x4(a, b, 0xdd);  // blocks a1, a3, b1, b3
#endif
            } else if constexpr (width == 8) {
#ifdef __AVX__
                const __m256 a = _mm256_loadu_ps(half(k, 0));
                const __m256 b = _mm256_loadu_ps(half(k + 4, 0));
                lo[k] = _mm256_permute2f128_ps(a, b, 0x20);
                hi[k] = _mm256_permute2f128_ps(a, b, 0x31);
#endif
            } else {
                lo[k] = _mm_loadu_ps(half(k, 0));
                hi[k] = _mm_loadu_ps(half(k, 1));
            }
        }
    }

    /// Stores 128-bit block `Block` of `r` to `out` (four floats, any alignment).
    template <unsigned Block>
    static void store_block(reg r, float* out) {
        if constexpr (width == 16) {
#ifdef __AVX512F__
            _mm_storeu_ps(out, _mm512_extractf32x4_ps(r, Block));
#endif
        } else if constexpr (width == 8) {
#ifdef __AVX__
            _mm_storeu_ps(out, Block == 0 ? _mm256_castps256_ps128(r) : _mm256_extractf128_ps(r, Block & 1));
#endif
        } else {
            _mm_storeu_ps(out, r);
        }
    }

    /// Writes halves `half` (0: values 0..3, 1: values 4..7) of the records
    /// from four coordinate vectors: the 4x4 transpose is its own inverse.
    template <class Put, unsigned... Blocks>
    static void store_half(const lanes<Arch> c[4], unsigned half, const Put& put,
                           std::integer_sequence<unsigned, Blocks...>) {
        const reg in[4] = {c[0], c[1], c[2], c[3]};
        lanes<Arch> r[4];
        transpose4(in, r);
        for (std::size_t k = 0; k < 4; ++k) {
            (store_block<Blocks>(r[k], put(k + 4 * Blocks) + 4 * half), ...);
        }
    }

    /// The inverse of load: writes lane i of the eight coordinate vectors `q`
    /// as the eight floats at put(i) (a float*), for every lane.
    template <class Put>
    static void store(const quad_lanes<Arch>& q, const Put& put) {
        using blocks = std::make_integer_sequence<unsigned, width / 4>;
        store_half(q.c, 0, put, blocks{});
        store_half(q.c + 4, 1, put, blocks{});
    }

    /// The rectangles pick(0) .. pick(width - 1) as quad_lanes, lane i from
    /// pick(i); InCache as in assemble.
    template <bool InCache = false, class Pick>
    static quad_lanes<Arch> load(const Pick& pick) {
        reg lo[4], hi[4];
        assemble<InCache>(pick, lo, hi);
        quad_lanes<Arch> q;
        transpose4(lo, q.c);
        transpose4(hi, q.c + 4);
        return q;
    }
};

}  // namespace
}  // namespace obbsat::detail
