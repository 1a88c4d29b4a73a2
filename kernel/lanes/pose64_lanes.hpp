// The methods on double poses, one pair per lane (2 per SSE2 vector, 4 per
// AVX2, 8 per AVX-512): local, conservative and the certified fast path of
// exact, doing the same double operations in the same order as their scalar
// references (obbsat/ref/local64.hpp and obbsat/ref/pose_conservative64.hpp
// state them), so verdicts are bit for bit the references'.
#pragma once

#include "lanes/pose64_record_transpose.hpp"

#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_pose64.hpp>

namespace obbsat::detail {
namespace {

template <class Arch>
struct pose64_steps {
    using batch = lanes64<Arch>;
    using mask = lane_mask64<Arch>;

    /// Steps 1 to 4 of local64.
    struct axes {
        batch offset[4];
        batch reach[4];
        batch dx, dy;
    };

    static OBBSAT_LANE_INLINE axes axes_of(const pose64_lanes<Arch>& a, const pose64_lanes<Arch>& b) {
        axes out;
        out.dx = b.cx - a.cx;
        out.dy = b.cy - a.cy;
        const batch P = xsimd::abs((a.c * b.c) + (a.s * b.s));
        const batch Q = xsimd::abs((a.c * b.s) - (a.s * b.c));
        const batch na = (a.c * a.c) + (a.s * a.s);
        const batch nb = (b.c * b.c) + (b.s * b.s);
        out.offset[0] = (out.dx * a.c) + (out.dy * a.s);
        out.reach[0] = ((a.hx * na) + (b.hx * P)) + (b.hy * Q);
        out.offset[1] = (out.dy * a.c) - (out.dx * a.s);
        out.reach[1] = ((a.hy * na) + (b.hx * Q)) + (b.hy * P);
        out.offset[2] = (out.dx * b.c) + (out.dy * b.s);
        out.reach[2] = ((b.hx * nb) + (a.hx * P)) + (a.hy * Q);
        out.offset[3] = (out.dy * b.c) - (out.dx * b.s);
        out.reach[3] = ((b.hy * nb) + (a.hx * Q)) + (a.hy * P);
        return out;
    }

    /// Steps 7 and 8 of pose_conservative64: A's and B's margins, and the
    /// lanes where they prove something. The reference's margin is +inf in
    /// the other lanes, where no gap can exceed it nor fall below its
    /// negation: a lane outside `proves` is left undecided (exact) or kept
    /// (conservative), which is what the callers do with the mask instead of
    /// blending infinities in.
    struct margins {
        batch a, b;
        mask proves;
    };

    static OBBSAT_LANE_INLINE margins margins_of(const pose64_lanes<Arch>& a, const pose64_lanes<Arch>& b,
                                                 const axes& x) {
        const batch D = xsimd::abs(x.dx) + xsimd::abs(x.dy);
        // Rotation components are finite (the store checks them), so max is the reference's fmax.
        const batch Ra = xsimd::max(xsimd::abs(a.c), xsimd::abs(a.s));
        const batch Rb = xsimd::max(xsimd::abs(b.c), xsimd::abs(b.s));
        const batch Ha = a.hx + a.hy;
        const batch Hb = b.hx + b.hy;
        const batch T = (D + (Ra * Ha)) + (Rb * Hb);
        const batch Sa = Ra * T;
        const batch Sb = Rb * T;
        // The reference's six bounds, two by two through max and min: no value
        // here is a NaN (Ra, Rb > 0 and finite, T >= 0), so "both <= t" is
        // "the larger <= t" and "both >= t" is "the smaller >= t".
        const mask proves = (xsimd::max(Sa, Sb) <= batch(0x1p1000)) & (xsimd::min(Ra, Rb) >= batch(0x1p-500)) &
                            (xsimd::max(Ra, Rb) <= batch(0x1p500));
        return margins{(batch(0x1p-48) * Sa) + batch(0x1p-1000), (batch(0x1p-48) * Sb) + batch(0x1p-1000), proves};
    }

    static OBBSAT_LANE_INLINE batch gap(const axes& x, unsigned k) { return xsimd::abs(x.offset[k]) - x.reach[k]; }

    /// The larger gap on A's axes and on B's. In a lane that `proves`, every
    /// offset and reach is finite (|offset| <= Ra * T and reach <= 6 Ra * T
    /// on A's axes, Rb on B's, and S = R * T <= 2^1000), so no gap is a NaN
    /// and "a gap beyond the margin" is "the larger gap beyond it", either way.
    struct widest {
        batch a, b;
    };

    static OBBSAT_LANE_INLINE widest widest_of(const axes& x) {
        return widest{xsimd::max(gap(x, 0), gap(x, 1)), xsimd::max(gap(x, 2), gap(x, 3))};
    }
};

template <class Arch>
struct local64_lanes {
    static constexpr bool has_slow_path = false;
    using steps = pose64_steps<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose64_lanes<Arch>& a, const pose64_lanes<Arch>& b) {
        const typename steps::axes x = steps::axes_of(a, b);
        typename steps::mask all = xsimd::abs(x.offset[0]) <= x.reach[0];
        for (unsigned k = 1; k < 4; ++k) {
            all = all & (xsimd::abs(x.offset[k]) <= x.reach[k]);
        }
        return lane_verdicts{lane_bits(all), 0};
    }
};

template <class Arch>
struct pose_conservative64_lanes {
    static constexpr bool has_slow_path = false;
    using steps = pose64_steps<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose64_lanes<Arch>& a, const pose64_lanes<Arch>& b) {
        const typename steps::axes x = steps::axes_of(a, b);
        const typename steps::margins m = steps::margins_of(a, b, x);
        const typename steps::widest g = steps::widest_of(x);
        const typename steps::mask apart = (g.a > m.a) | (g.b > m.b);
        return lane_verdicts{lane_bits(~(m.proves & apart)), 0};
    }
};

/// Method exact on double poses: the certified fast path decides a lane when
/// an axis proves it apart or all four prove overlap; the double pose oracle
/// settles the lanes it leaves undecided.
template <class Arch>
struct pose_exact64_lanes {
    static constexpr bool has_slow_path = true;
    using steps = pose64_steps<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose64_lanes<Arch>& a, const pose64_lanes<Arch>& b) {
        const typename steps::axes x = steps::axes_of(a, b);
        const typename steps::margins m = steps::margins_of(a, b, x);
        const typename steps::widest g = steps::widest_of(x);
        // Margins are >= 2^-1000: never a zero whose sign a backend could flip.
        const typename steps::mask apart = (g.a > m.a) | (g.b > m.b);
        const typename steps::mask overlapping = (g.a < -m.a) & (g.b < -m.b);
        const typename steps::mask hit = m.proves & overlapping;
        return lane_verdicts{lane_bits(hit), lane_bits(~(hit | (m.proves & apart)))};
    }

    static bool decide_exactly(const rect_pose64& a, const rect_pose64& b) { return oracle::intersects(a, b); }
};

}  // namespace
}  // namespace obbsat::detail
