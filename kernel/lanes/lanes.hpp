// Vocabulary of the SIMD kernel: one pair per lane, corners in structure-of-
// arrays form, and the steps every method shares, written once over the xsimd
// architecture.
//
// Everything here has internal linkage (an unnamed namespace) because this
// header is compiled into one translation unit per instruction set, each with
// its own flags: a shared inline function with external linkage could be
// merged by the linker into the copy built for a wider ISA.
#pragma once

#include "dispatch/soa_view.hpp"

#include <xsimd/xsimd.hpp>

#include <cstdint>
#include <cstring>
#include <type_traits>

// The lane steps are small and called once per vector from the batch loops;
// left to itself GCC keeps a method's collide() out of line, and every call
// then spills sixteen vectors of corners to the stack and reloads them.
#define OBBSAT_LANE_INLINE __attribute__((always_inline)) inline

namespace obbsat::detail {
namespace {

template <class Arch>
using lanes = xsimd::batch<float, Arch>;

template <class Arch>
using lane_mask = xsimd::batch_bool<float, Arch>;

/// The corners of one rectangle per lane, as eight coordinate vectors in
/// rect_soa order: ulx, uly, urx, ury, lrx, lry, llx, lly. Batch is an xsimd
/// batch of float (the input) or of double (methods that compute in double).
template <class Batch>
struct quad {
    Batch c[coord_count];

    const Batch& x(unsigned corner) const { return c[2 * corner]; }
    const Batch& y(unsigned corner) const { return c[2 * corner + 1]; }
};

template <class Arch>
using quad_lanes = quad<lanes<Arch>>;

enum corner_index : unsigned { UL = 0, UR = 1, LR = 2, LL = 3 };

/// The reference's min-pick, u < v ? u : v. On x86, xsimd::min(u, v) is one
/// MINPS (MINPD) with u as the first operand, which returns exactly that (the
/// second operand on equality, on -0 vs +0 and on NaN), so no blend is needed.
template <class Batch>
Batch min_pick(const Batch& u, const Batch& v) {
    return xsimd::min(u, v);
}

/// The reference's max-pick, u > v ? u : v: one MAXPS (MAXPD), as min_pick.
template <class Batch>
Batch max_pick(const Batch& u, const Batch& v) {
    return xsimd::max(u, v);
}

/// The lanes whose mask is set, lane 0 in bit 0, for float or double masks.
template <class T, class Arch>
unsigned lane_bits(const xsimd::batch_bool<T, Arch>& mask) {
    constexpr bool is_float = std::is_same<T, float>::value;
    if constexpr (std::is_base_of<xsimd::avx512f, Arch>::value) {
        return static_cast<unsigned>(mask.data);
    } else if constexpr (std::is_base_of<xsimd::avx, Arch>::value) {
#ifdef __AVX__
        if constexpr (is_float) {
            return static_cast<unsigned>(_mm256_movemask_ps(mask));
        } else {
            return static_cast<unsigned>(_mm256_movemask_pd(mask));
        }
#endif
    } else {
        if constexpr (is_float) {
            return static_cast<unsigned>(_mm_movemask_ps(mask));
        } else {
            return static_cast<unsigned>(_mm_movemask_pd(mask));
        }
    }
}

/// A method's answer for one vector of pairs: lane i collides iff bit i of
/// `hit` is set, unless bit i of `unsure` is set: then the fast path could not
/// decide and the method's decide_exactly settles that lane.
struct lane_verdicts {
    unsigned hit;
    unsigned unsure;
};

/// One lane's two rectangles (or poses), for a method's decide_exactly. Not
/// std::pair: its members, like every std:: template, have vague linkage, and
/// baseline code instantiates them too (lanes/README.md).
template <class Shape>
struct lane_pair {
    Shape first;
    Shape second;
};

template <class Shape>
lane_pair<Shape> make_lane_pair(const Shape& a, const Shape& b) {
    return lane_pair<Shape>{a, b};
}

/// Spreads the low 8 bits of `bits` into 8 bytes of value 0 or 1, bit i into byte i.
inline std::uint64_t spread_bits_to_bytes(unsigned bits) {
    const std::uint64_t replicated = (bits & 0xffu) * 0x0101010101010101ull;
    const std::uint64_t isolated = replicated & 0x8040201008040201ull;
    return ((isolated + 0x7f7f7f7f7f7f7f7full) >> 7) & 0x0101010101010101ull;
}

/// Writes `count` (at most `Width`) verdict bytes, byte i from bit i of `bits`.
template <std::size_t Width>
void store_verdicts(unsigned bits, std::uint8_t* out, std::size_t count) {
    std::uint8_t bytes[Width < 8 ? 8 : Width];
    for (std::size_t k = 0; k < Width; k += 8) {
        const std::uint64_t word = spread_bits_to_bytes(bits >> k);
        std::memcpy(bytes + k, &word, 8);
    }
    std::memcpy(out, bytes, count);
}

}  // namespace
}  // namespace obbsat::detail
