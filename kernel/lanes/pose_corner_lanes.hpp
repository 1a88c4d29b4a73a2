// Poses to corner records in SIMD: the float operations of
// obbsat::ref::corners_of(const rect_pose&) (obbsat/ref/pose_corners.hpp), in
// the same order, one pose per lane, read and written as whole 32-byte records.
#pragma once

#include "lanes/pose_batch.hpp"
#include "lanes/record_transpose.hpp"

#include <cstring>

namespace obbsat::detail {
namespace {

/// The corners UL, UR, LR, LL of one pose per lane, in rect order.
template <class Arch>
OBBSAT_LANE_INLINE quad_lanes<Arch> corners_of(const pose_lanes<Arch>& p) {
    using batch = lanes<Arch>;
    const batch ux = p.hx * p.c;
    const batch uy = p.hx * p.s;
    const batch wx = p.hy * p.s;  // v = (-wx, vy); never negated: see obbsat/ref/pose_corners.hpp
    const batch vy = p.hy * p.c;
    const batch left_x = p.cx - ux;
    const batch left_y = p.cy - uy;
    const batch right_x = p.cx + ux;
    const batch right_y = p.cy + uy;
    return quad_lanes<Arch>{{left_x - wx, left_y + vy, right_x - wx, right_y + vy, right_x + wx, right_y - vy,
                             left_x + wx, left_y - vy}};
}

/// out[i] = the corners of pose record i, for i < count.
template <class Arch>
void pose_corners_batch(const float* records, std::size_t count, rect* out) {
    constexpr std::size_t width = lanes<Arch>::size;
    std::size_t i = 0;
    for (; i + width <= count; i += width) {
        const quad_lanes<Arch> corners =
            corners_of(load_poses<Arch>(records + pose_record_floats * i, [](std::size_t lane) { return lane; }));
        record_transpose<Arch>::store(corners, [&](std::size_t lane) { return reinterpret_cast<float*>(out + i + lane); });
    }
    if (i < count) {
        // The last poses through a full vector of local records (zeros pad it).
        const std::size_t valid = count - i;
        alignas(64) float staged_in[width * pose_record_floats] = {};
        alignas(64) rect staged_out[width];
        std::memcpy(staged_in, records + pose_record_floats * i, valid * pose_record_floats * sizeof(float));
        const quad_lanes<Arch> corners = corners_of(load_poses<Arch>(staged_in, [](std::size_t lane) { return lane; }));
        record_transpose<Arch>::store(corners, [&](std::size_t lane) { return reinterpret_cast<float*>(staged_out + lane); });
        std::memcpy(out + i, staged_out, valid * sizeof(rect));
    }
}

}  // namespace
}  // namespace obbsat::detail
