// The methods on double corners (rect_records64), one pair per lane of
// doubles (2 per SSE2 vector, 4 per AVX2, 8 per AVX-512), doing the double
// operations of their scalar references in the same order, so that verdicts
// are bit for bit theirs:
//   exact         the certified fast path of obbsat/ref/certified64.hpp (the
//                 steps of certified_lanes.hpp in double); the lanes it leaves
//                 undecided are settled by the exact oracle of
//                 obbsat/oracle/contact64.hpp, as obbsat/ref/exact64.hpp says;
//   conservative  obbsat/ref/conservative64.hpp, its fused projections and
//                 margin computed by fused_multiply_add (one rounding each).
// And the batch driver: a vector of pairs at a time, each lane's two records
// read whole and transposed in registers (record64_transpose.hpp).
#pragma once

#include "lanes/batch_kernel.hpp"
#include "lanes/certified_lanes.hpp"
#include "lanes/fused_multiply_add.hpp"
#include "lanes/lanes.hpp"
#include "lanes/record64_transpose.hpp"
#include "lanes/sat4_lanes.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// One double-corner rectangle per lane.
template <class Arch>
using quad64_lanes = quad<xsimd::batch<double, Arch>>;

/// Method exact on double corners: proven lanes from the certified path in
/// double, the rest from the double oracle.
template <class Arch>
struct corner_exact64_lanes {
    static constexpr bool has_slow_path = true;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b) {
        const auto v = certified_steps<Arch, double>::certify(a, b);
        return lane_verdicts{lane_bits(v.intersecting), lane_bits(~(v.separated | v.intersecting))};
    }

    static bool decide_exactly(const rect64& a, const rect64& b) { return oracle::intersects(a, b); }
};

/// Method conservative on double corners, steps 1 to 7 of conservative64.hpp.
template <class Arch>
struct corner_conservative64_lanes {
    static constexpr bool has_slow_path = false;

    using batch = xsimd::batch<double, Arch>;
    using mask = xsimd::batch_bool<double, Arch>;

    /// Steps 1 and 2: (K · 2^513) · 0x1.004p-563, +inf where K >= 2^511. The
    /// magnitudes are finite and not negative, so their largest is the same
    /// in any order and max is the reference's max-pick.
    static OBBSAT_LANE_INLINE batch margin_scale(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b) {
        batch k = xsimd::abs(a.c[0]);
        for (unsigned i = 1; i < coord_count; ++i) {
            k = xsimd::max(k, xsimd::abs(a.c[i]));
        }
        for (unsigned i = 0; i < coord_count; ++i) {
            k = xsimd::max(k, xsimd::abs(b.c[i]));
        }
        return (k * batch(0x1p513)) * batch(0x1.004p-563);
    }

    /// Steps 4 and 5: min and max of the four scalars fma(x, ax, y · ay), folded UL, UR, LR, LL.
    static OBBSAT_LANE_INLINE void project(const quad64_lanes<Arch>& q, const batch& ax, const batch& ay, batch& lo,
                                           batch& hi) {
        batch s[4];
        for (unsigned k = 0; k < 4; ++k) {
            s[k] = fused_multiply_add<Arch>(q.x(k), ax, q.y(k) * ay);
        }
        sat4_steps<batch>::fold(s, lo, hi);
    }

    /// Steps 6 and 7 on one axis: the lanes it proves apart (never one whose difference or margin is NaN).
    static OBBSAT_LANE_INLINE mask proven_apart_on(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b,
                                                   const batch& ax, const batch& ay, const batch& scale) {
        batch min_a, max_a, min_b, max_b;
        project(a, ax, ay, min_a, max_a);
        project(b, ax, ay, min_b, max_b);
        const batch margin =
            fused_multiply_add<Arch>(scale, max_pick(xsimd::abs(ax), xsimd::abs(ay)), batch(0x1p-1000));
        return max_pick(min_b - max_a, min_a - max_b) > margin;
    }

    static OBBSAT_LANE_INLINE lane_verdicts collide(const quad64_lanes<Arch>& a, const quad64_lanes<Arch>& b) {
        const batch scale = margin_scale(a, b);
        // Step 3, the article's axes A.UR - A.UL, A.UR - A.LR, B.UL - B.LL, B.UL - B.UR.
        const mask apart_on_a = proven_apart_on(a, b, a.x(UR) - a.x(UL), a.y(UR) - a.y(UL), scale) |
                                proven_apart_on(a, b, a.x(UR) - a.x(LR), a.y(UR) - a.y(LR), scale);
        // B's axes cannot change a lane A's axes already proved apart.
        if (xsimd::all(apart_on_a)) {
            return lane_verdicts{0, 0};
        }
        const mask apart = apart_on_a | proven_apart_on(a, b, b.x(UL) - b.x(LL), b.y(UL) - b.y(LL), scale) |
                           proven_apart_on(a, b, b.x(UL) - b.x(UR), b.y(UL) - b.y(UR), scale);
        return lane_verdicts{lane_bits(~apart), 0};
    }
};

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count
/// over rect_records64 records; returns the lanes settled exactly. The last,
/// partial vector repeats its last pair in the unused lanes and stores only
/// its own verdicts, so nothing past the caller's arrays is read or written.
template <class Arch, template <class> class Method>
std::size_t corner64_indexed_batch(const rect64* records, const pair_index* pairs, std::size_t count,
                                   std::uint8_t* verdicts) {
    using transpose = record64_transpose<Arch>;
    constexpr std::size_t width = transpose::width;
    std::size_t settled = 0;
    auto rects_of = [&](std::size_t pair) { return make_lane_pair(records[pairs[pair].a], records[pairs[pair].b]); };
    // One vector of pairs from i, pair_of(lane) giving each lane's pair.
    auto run = [&](std::size_t i, std::size_t valid, const auto& pair_of) __attribute__((always_inline)) {
        const lane_verdicts v =
            Method<Arch>::collide(transpose::load([&](std::size_t lane) { return records + pairs[pair_of(lane)].a; }),
                                  transpose::load([&](std::size_t lane) { return records + pairs[pair_of(lane)].b; }));
        settled += finish_vector<width, Method, Arch>(v, verdicts + i, valid,
                                                      [&](std::size_t lane) { return rects_of(i + lane); });
    };
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        run(i, width, [&](std::size_t lane) { return i + lane; });
    }
    if (i < count) {
        const std::size_t valid = count - i;
        run(i, valid, [&](std::size_t lane) { return i + (lane < valid ? lane : valid - 1); });
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
