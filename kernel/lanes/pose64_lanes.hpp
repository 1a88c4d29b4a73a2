// The methods on double poses, one pair per lane (2 per SSE2 vector, 4 per
// AVX2, 8 per AVX-512): local, conservative and the certified fast path of
// exact, doing the same double operations in the same order as their scalar
// references (obbsat/ref/local64.hpp and obbsat/ref/pose_conservative64.hpp
// state them), so verdicts are bit for bit the references'.
#pragma once

#include "lanes/lanes.hpp"

#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <limits>

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

/// One vector of poses gathered lane by lane from pose_records64 records.
template <class Arch>
struct staged_poses64 {
    static constexpr std::size_t width = lanes64<Arch>::size;
    alignas(64) double values[6][width];

    void put(std::size_t lane, const double* record) {
        for (unsigned f = 0; f < 6; ++f) {
            values[f][lane] = record[f];
        }
    }

    pose64_lanes<Arch> load() const {
        using batch = lanes64<Arch>;
        return pose64_lanes<Arch>{batch::load_aligned(values[0]), batch::load_aligned(values[1]),
                                  batch::load_aligned(values[2]), batch::load_aligned(values[3]),
                                  batch::load_aligned(values[4]), batch::load_aligned(values[5])};
    }
};

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

    /// Steps 7 and 8 of pose_conservative64: A's and B's margins, +inf where
    /// the pair proves nothing.
    struct margins {
        batch a, b;
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
        const mask proves = (Sa <= batch(0x1p1000)) & (Sb <= batch(0x1p1000)) & (Ra >= batch(0x1p-500)) &
                            (Ra <= batch(0x1p500)) & (Rb >= batch(0x1p-500)) & (Rb <= batch(0x1p500));
        // A constant, not a call (lanes/README.md).
        constexpr double infinity = std::numeric_limits<double>::infinity();
        const batch none(infinity);
        return margins{xsimd::select(proves, (batch(0x1p-48) * Sa) + batch(0x1p-1000), none),
                       xsimd::select(proves, (batch(0x1p-48) * Sb) + batch(0x1p-1000), none)};
    }

    static OBBSAT_LANE_INLINE batch gap(const axes& x, unsigned k) { return xsimd::abs(x.offset[k]) - x.reach[k]; }
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
        typename steps::mask apart = steps::gap(x, 0) > m.a;
        for (unsigned k = 1; k < 4; ++k) {
            apart = apart | (steps::gap(x, k) > (k < 2 ? m.a : m.b));
        }
        return lane_verdicts{lane_bits(~apart), 0};
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
        // Margins are >= 2^-1000 or +inf: never a zero whose sign a backend could flip.
        typename steps::mask apart = steps::gap(x, 0) > m.a;
        typename steps::mask overlapping = steps::gap(x, 0) < -m.a;
        for (unsigned k = 1; k < 4; ++k) {
            const typename steps::batch g = steps::gap(x, k);
            const typename steps::batch margin = k < 2 ? m.a : m.b;
            apart = apart | (g > margin);
            overlapping = overlapping & (g < -margin);
        }
        return lane_verdicts{lane_bits(overlapping), lane_bits(~(apart | overlapping))};
    }

    static bool decide_exactly(const rect_pose64& a, const rect_pose64& b) { return oracle::intersects(a, b); }
};

/// Pose `index` of pose_records64 records, as the store's operator[] reads it.
inline rect_pose64 pose64_at(const double* records, std::size_t index) {
    const double* r = records + index * pose_records64::record_doubles;
    return rect_pose64{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}};
}

/// verdicts[i] = Method(records[pairs[i].a], records[pairs[i].b]) for i < count;
/// returns the lanes settled exactly. A partial last vector repeats its last
/// pair in the unused lanes and stores only its own verdicts.
template <class Arch, template <class> class Method>
std::size_t pose64_indexed_batch(const double* records, const pair_index* pairs, std::size_t count,
                                 std::uint8_t* verdicts) {
    constexpr std::size_t width = lanes64<Arch>::size;
    constexpr std::size_t stride = pose_records64::record_doubles;
    staged_poses64<Arch> sa, sb;
    std::size_t settled = 0;
    for (std::size_t i = 0; i < count; i += width) {
        const std::size_t valid = (count - i < width) ? count - i : width;
        for (std::size_t lane = 0; lane < width; ++lane) {
            const pair_index& p = pairs[i + (lane < valid ? lane : valid - 1)];
            sa.put(lane, records + p.a * stride);
            sb.put(lane, records + p.b * stride);
        }
        const lane_verdicts v = Method<Arch>::collide(sa.load(), sb.load());
        store_verdicts<width>(v.hit, verdicts + i, valid);
        if constexpr (Method<Arch>::has_slow_path) {
            for (unsigned unsure = v.unsure; unsure != 0; unsure &= unsure - 1) {
                const std::size_t lane = static_cast<std::size_t>(__builtin_ctz(unsure));
                if (lane < valid) {
                    const pair_index& p = pairs[i + lane];
                    verdicts[i + lane] =
                        Method<Arch>::decide_exactly(pose64_at(records, p.a), pose64_at(records, p.b)) ? 1 : 0;
                    ++settled;
                }
            }
        }
    }
    return settled;
}

}  // namespace
}  // namespace obbsat::detail
