// The methods on poses, one pair per lane: local, conservative and the
// certified fast path of exact, doing the same float operations in the same
// order as their scalar references (obbsat/ref/local.hpp and
// obbsat/ref/pose_conservative.hpp state them).
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/oracle/pose_contact.hpp>
#include <obbsat/rect_pose.hpp>

#include <limits>

namespace obbsat::detail {
namespace {

/// One pose per lane: center, half extents, rotation vector.
template <class Arch>
struct pose_lanes {
    lanes<Arch> cx, cy, hx, hy, c, s;
};

/// Loads the poses of a vector of 32-byte records (cx, cy, hx, hy, c, s, 0, 0),
/// transposed as rect records are: coordinate k of the record is value k.
template <class Arch>
OBBSAT_LANE_INLINE pose_lanes<Arch> poses_of(const quad_lanes<Arch>& q) {
    return pose_lanes<Arch>{q.c[0], q.c[1], q.c[2], q.c[3], q.c[4], q.c[5]};
}

template <class Arch>
struct pose_steps {
    using batch = lanes<Arch>;
    using mask = lane_mask<Arch>;

    /// Steps 1 to 4 of local, kept per lane.
    struct axes {
        batch offset[4];
        batch reach[4];
        batch dx, dy;
    };

    /// Steps 1 to 4 on A's two axes only (enough for the early out).
    static OBBSAT_LANE_INLINE void first_axes(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b, axes& out,
                                              batch& P, batch& Q) {
        out.dx = b.cx - a.cx;
        out.dy = b.cy - a.cy;
        P = xsimd::abs((a.c * b.c) + (a.s * b.s));
        Q = xsimd::abs((a.c * b.s) - (a.s * b.c));
        const batch na = (a.c * a.c) + (a.s * a.s);
        out.offset[0] = (out.dx * a.c) + (out.dy * a.s);
        out.reach[0] = ((a.hx * na) + (b.hx * P)) + (b.hy * Q);
        out.offset[1] = (out.dy * a.c) - (out.dx * a.s);
        out.reach[1] = ((a.hy * na) + (b.hx * Q)) + (b.hy * P);
    }

    /// Steps 1 to 4 on B's two axes, after first_axes.
    static OBBSAT_LANE_INLINE void second_axes(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b, axes& out,
                                               const batch& P, const batch& Q) {
        const batch nb = (b.c * b.c) + (b.s * b.s);
        out.offset[2] = (out.dx * b.c) + (out.dy * b.s);
        out.reach[2] = ((b.hx * nb) + (a.hx * P)) + (a.hy * Q);
        out.offset[3] = (out.dy * b.c) - (out.dx * b.s);
        out.reach[3] = ((b.hy * nb) + (a.hx * Q)) + (a.hy * P);
    }

    /// Steps 7 and 8 of the pose conservative method: the margins of A's axes
    /// and of B's, +inf where the pair proves nothing.
    struct margins {
        batch a, b;
    };
    static OBBSAT_LANE_INLINE margins margins_of(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b,
                                                 const axes& x) {
        const batch D = xsimd::abs(x.dx) + xsimd::abs(x.dy);
        // Rotation components are finite, so max is the reference's fmax.
        const batch Ra = xsimd::max(xsimd::abs(a.c), xsimd::abs(a.s));
        const batch Rb = xsimd::max(xsimd::abs(b.c), xsimd::abs(b.s));
        const batch Ha = a.hx + a.hy;
        const batch Hb = b.hx + b.hy;
        const batch T = (D + (Ra * Ha)) + (Rb * Hb);
        const batch Sa = Ra * T;
        const batch Sb = Rb * T;
        const mask proves = (Sa <= batch(0x1p100f)) & (Sb <= batch(0x1p100f)) & (Ra >= batch(0x1p-40f)) &
                            (Ra <= batch(0x1p62f)) & (Rb >= batch(0x1p-40f)) & (Rb <= batch(0x1p62f));
        // A constant, not a call: std::numeric_limits<float>::infinity() left
        // out of line (-O0) is a function of vague linkage (lanes/README.md).
        constexpr float infinity = std::numeric_limits<float>::infinity();
        const batch none(infinity);
        return margins{xsimd::select(proves, (batch(0x1p-19f) * Sa) + batch(0x1p-140f), none),
                       xsimd::select(proves, (batch(0x1p-19f) * Sb) + batch(0x1p-140f), none)};
    }

    static OBBSAT_LANE_INLINE batch gap(const axes& x, unsigned k) { return xsimd::abs(x.offset[k]) - x.reach[k]; }
};

template <class Arch>
struct local_lanes {
    static constexpr bool has_slow_path = false;
    using steps = pose_steps<Arch>;
    using batch = lanes<Arch>;
    using mask = lane_mask<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b) {
        typename steps::axes x;
        batch P, Q;
        steps::first_axes(a, b, x, P, Q);
        const mask on_a = (xsimd::abs(x.offset[0]) <= x.reach[0]) & (xsimd::abs(x.offset[1]) <= x.reach[1]);
        // As the article says: B's axes cannot change a lane A's axes already separated.
        if (xsimd::none(on_a)) {
            return lane_verdicts{0, 0};
        }
        steps::second_axes(a, b, x, P, Q);
        const mask all = on_a & (xsimd::abs(x.offset[2]) <= x.reach[2]) & (xsimd::abs(x.offset[3]) <= x.reach[3]);
        return lane_verdicts{lane_bits(all), 0};
    }
};

template <class Arch>
struct pose_conservative_lanes {
    static constexpr bool has_slow_path = false;
    using steps = pose_steps<Arch>;
    using batch = lanes<Arch>;
    using mask = lane_mask<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b) {
        typename steps::axes x;
        batch P, Q;
        steps::first_axes(a, b, x, P, Q);
        const typename steps::margins m = steps::margins_of(a, b, x);
        const mask apart_on_a = (steps::gap(x, 0) > m.a) | (steps::gap(x, 1) > m.a);
        if (xsimd::all(apart_on_a)) {
            return lane_verdicts{0, 0};
        }
        steps::second_axes(a, b, x, P, Q);
        const mask apart = apart_on_a | (steps::gap(x, 2) > m.b) | (steps::gap(x, 3) > m.b);
        return lane_verdicts{lane_bits(~apart), 0};
    }
};

/// Method exact on poses: the certified fast path decides a lane when an axis
/// proves it apart or all four prove overlap; the exact pose oracle settles
/// the lanes it leaves undecided.
template <class Arch>
struct pose_exact_lanes {
    static constexpr bool has_slow_path = true;
    using steps = pose_steps<Arch>;
    using batch = lanes<Arch>;
    using mask = lane_mask<Arch>;

    static OBBSAT_LANE_INLINE lane_verdicts collide(const pose_lanes<Arch>& a, const pose_lanes<Arch>& b) {
        typename steps::axes x;
        batch P, Q;
        steps::first_axes(a, b, x, P, Q);
        steps::second_axes(a, b, x, P, Q);
        const typename steps::margins m = steps::margins_of(a, b, x);
        // Margins are >= 2^-140 or +inf: never a zero whose sign a backend could flip.
        mask apart = steps::gap(x, 0) > m.a;
        mask overlapping = steps::gap(x, 0) < -m.a;
        for (unsigned k = 1; k < 4; ++k) {
            const batch g = steps::gap(x, k);
            const batch margin = k < 2 ? m.a : m.b;
            apart = apart | (g > margin);
            overlapping = overlapping & (g < -margin);
        }
        return lane_verdicts{lane_bits(overlapping), lane_bits(~(apart | overlapping))};
    }

    static bool decide_exactly(const rect_pose& a, const rect_pose& b) { return oracle::intersects(a, b); }
};

}  // namespace
}  // namespace obbsat::detail
