// Storing one vector of double contacts: the twelve field vectors of a
// contact64 (nx, ny, depth, count, then x, y, separation, feature of each
// point, every one as wide as a double) transposed in registers into each
// lane's 96-byte contact. Staging the fields through memory instead (a
// vector store a field, then twelve scalar reads a lane) spent more time
// moving a scene's double contacts than the transposes take.
//
// A contact is three 32-byte quarters of four fields each, so the store is
// a 4x4 transpose of doubles per quarter and per four lanes:
//   SSE2     a 2x2 per pair of fields: unpack low and high;
//   AVX2     a 4x4 per quarter: unpack within 128-bit blocks, then regroup
//            the blocks (vperm2f128);
//   AVX-512  the AVX2 transpose on each 256-bit half of the fields.
// Each translation unit is compiled for one ISA, so the branches for wider
// ones are compiled out with the ISA's own predefined macros.
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/contact_manifold.hpp>

#include <cstddef>

namespace obbsat::detail {
namespace {

template <class Arch>
struct contact64_transpose {
    using batch = xsimd::batch<double, Arch>;
    static constexpr std::size_t width = batch::size;

    static_assert(sizeof(contact64) == 12 * sizeof(double), "a double contact is twelve doubles");

    /// Writes lane i of the twelve fields f[0 .. 12) as the contact64 at
    /// place(i) (a contact64*), for every lane.
    template <class Place>
    static OBBSAT_LANE_INLINE void store(const batch* f, const Place& place) {
        auto to = [&](std::size_t lane) { return reinterpret_cast<double*>(place(lane)); };
        if constexpr (width == 8) {
#ifdef __AVX512F__
            for (std::size_t quarter = 0; quarter < 3; ++quarter) {
                const __m512d v[4] = {f[4 * quarter], f[4 * quarter + 1], f[4 * quarter + 2], f[4 * quarter + 3]};
                __m256d low[4], high[4];
                for (std::size_t k = 0; k < 4; ++k) {
                    low[k] = _mm512_castpd512_pd256(v[k]);
                    high[k] = _mm512_extractf64x4_pd(v[k], 1);
                }
                store_transposed(low, to(0) + 4 * quarter, to(1) + 4 * quarter, to(2) + 4 * quarter,
                                 to(3) + 4 * quarter);
                store_transposed(high, to(4) + 4 * quarter, to(5) + 4 * quarter, to(6) + 4 * quarter,
                                 to(7) + 4 * quarter);
            }
#endif
        } else if constexpr (width == 4) {
#ifdef __AVX__
            for (std::size_t quarter = 0; quarter < 3; ++quarter) {
                const __m256d v[4] = {f[4 * quarter], f[4 * quarter + 1], f[4 * quarter + 2], f[4 * quarter + 3]};
                store_transposed(v, to(0) + 4 * quarter, to(1) + 4 * quarter, to(2) + 4 * quarter,
                                 to(3) + 4 * quarter);
            }
#endif
        } else {
            for (std::size_t pair = 0; pair < 6; ++pair) {
                const __m128d first = f[2 * pair], second = f[2 * pair + 1];
                _mm_storeu_pd(to(0) + 2 * pair, _mm_unpacklo_pd(first, second));
                _mm_storeu_pd(to(1) + 2 * pair, _mm_unpackhi_pd(first, second));
            }
        }
    }

private:
#ifdef __AVX__
    /// Writes lane k of the four fields v[0 .. 4) as the four doubles at tk.
    static OBBSAT_LANE_INLINE void store_transposed(const __m256d* v, double* t0, double* t1, double* t2,
                                                    double* t3) {
        // Fields (0, 1) and (2, 3) of lanes (0, 2) and (1, 3), a lane per 128-bit block.
        const __m256d low01 = _mm256_unpacklo_pd(v[0], v[1]);
        const __m256d high01 = _mm256_unpackhi_pd(v[0], v[1]);
        const __m256d low23 = _mm256_unpacklo_pd(v[2], v[3]);
        const __m256d high23 = _mm256_unpackhi_pd(v[2], v[3]);
        _mm256_storeu_pd(t0, _mm256_permute2f128_pd(low01, low23, 0x20));
        _mm256_storeu_pd(t1, _mm256_permute2f128_pd(high01, high23, 0x20));
        _mm256_storeu_pd(t2, _mm256_permute2f128_pd(low01, low23, 0x31));
        _mm256_storeu_pd(t3, _mm256_permute2f128_pd(high01, high23, 0x31));
    }
#endif
};

}  // namespace
}  // namespace obbsat::detail
