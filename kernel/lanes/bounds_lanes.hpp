// The bounds of the scene queries in SIMD: the float operations of
// obbsat::ref::bounds_of (obbsat/ref/bounds.hpp) for poses and for corners, in
// the same order, one rectangle per lane, read as whole 32-byte records and
// written as four arrays. Internal linkage, as every lane header compiled
// into the per-ISA units.
#pragma once

#include "lanes/pose_batch.hpp"
#include "lanes/record_transpose.hpp"

#include <obbsat/method.hpp>

#include <cstring>

namespace obbsat::detail {
namespace {

template <class Arch>
struct bounds_lanes {
    lanes<Arch> lo_x, lo_y, hi_x, hi_y;
};

/// std::min(u, v), which is v < u ? v : u: min_pick with its operands swapped.
template <class Batch>
OBBSAT_LANE_INLINE Batch std_min(const Batch& u, const Batch& v) {
    return min_pick(v, u);
}

/// std::max(u, v), which is u < v ? v : u: max_pick with its operands swapped.
template <class Batch>
OBBSAT_LANE_INLINE Batch std_max(const Batch& u, const Batch& v) {
    return max_pick(v, u);
}

template <class Arch>
OBBSAT_LANE_INLINE bounds_lanes<Arch> bounds_of(const pose_lanes<Arch>& p) {
    using batch = lanes<Arch>;
    const batch ac = xsimd::abs(p.c);
    const batch as = xsimd::abs(p.s);
    const batch ex = (ac * p.hx) + (as * p.hy);
    const batch ey = (as * p.hx) + (ac * p.hy);
    const batch mx = ((xsimd::abs(p.cx) + ex) * batch(0x1p-21f)) + batch(0x1p-140f);
    const batch my = ((xsimd::abs(p.cy) + ey) * batch(0x1p-21f)) + batch(0x1p-140f);
    return bounds_lanes<Arch>{(p.cx - ex) - mx, (p.cy - ey) - my, (p.cx + ex) + mx, (p.cy + ey) + my};
}

template <class Arch>
OBBSAT_LANE_INLINE bounds_lanes<Arch> bounds_of(const quad_lanes<Arch>& q) {
    return bounds_lanes<Arch>{
        std_min(std_min(q.x(UL), q.x(UR)), std_min(q.x(LR), q.x(LL))),
        std_min(std_min(q.y(UL), q.y(UR)), std_min(q.y(LR), q.y(LL))),
        std_max(std_max(q.x(UL), q.x(UR)), std_max(q.x(LR), q.x(LL))),
        std_max(std_max(q.y(UL), q.y(UR)), std_max(q.y(LR), q.y(LL))),
    };
}

template <class Arch>
OBBSAT_LANE_INLINE bounds_lanes<Arch> bounds_at(store_kind kind, const float* records) {
    const quad_lanes<Arch> q = record_transpose<Arch>::load(
        [&](std::size_t lane) { return reinterpret_cast<const rect*>(records + 8 * lane); });
    return kind == store_kind::poses ? bounds_of<Arch>(poses_of<Arch>(q)) : bounds_of<Arch>(q);
}

/// lo_x[i], lo_y[i], hi_x[i], hi_y[i] = ref::bounds_of(record i) for i < count,
/// over 32-byte records of `kind` (pose records or corner records).
template <class Arch>
void bounds_batch(store_kind kind, const float* records, std::size_t count, float* lo_x, float* lo_y, float* hi_x,
                  float* hi_y) {
    using batch = lanes<Arch>;
    constexpr std::size_t width = batch::size;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const bounds_lanes<Arch> b = bounds_at<Arch>(kind, records + 8 * i);
        b.lo_x.store_unaligned(lo_x + i);
        b.lo_y.store_unaligned(lo_y + i);
        b.hi_x.store_unaligned(hi_x + i);
        b.hi_y.store_unaligned(hi_y + i);
    }
    if (i < count) {
        // The last records through a full vector of local records (zeros pad it).
        const std::size_t valid = count - i;
        alignas(64) float staged[width * 8] = {};
        alignas(64) float out[4][width];
        std::memcpy(staged, records + 8 * i, valid * 8 * sizeof(float));
        const bounds_lanes<Arch> b = bounds_at<Arch>(kind, staged);
        b.lo_x.store_aligned(out[0]);
        b.lo_y.store_aligned(out[1]);
        b.hi_x.store_aligned(out[2]);
        b.hi_y.store_aligned(out[3]);
        std::memcpy(lo_x + i, out[0], valid * sizeof(float));
        std::memcpy(lo_y + i, out[1], valid * sizeof(float));
        std::memcpy(hi_x + i, out[2], valid * sizeof(float));
        std::memcpy(hi_y + i, out[3], valid * sizeof(float));
    }
}

}  // namespace
}  // namespace obbsat::detail
