// What the kernels see of a pose_soa64: six double field arrays, shifted as a
// batch is split over threads. Plain data, with its helpers of internal
// linkage: the per-ISA kernels read it too (kernel/lanes/README.md).
#pragma once

#include <obbsat/pose_soa64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstddef>

namespace obbsat::detail {

struct pose_soa64_view {
    const double* fields[pose_field_count];  // cx, cy, hx, hy, c, s
};

namespace {

/// The pose at `i` of `v`, assembled from the six arrays.
inline rect_pose64 pose64_at(const pose_soa64_view& v, std::size_t i) {
    return rect_pose64{{v.fields[0][i], v.fields[1][i]}, {v.fields[2][i], v.fields[3][i]},
                       {v.fields[4][i], v.fields[5][i]}};
}

/// The arrays of `v` starting `offset` poses later.
inline pose_soa64_view shifted(const pose_soa64_view& v, std::size_t offset) {
    pose_soa64_view out = v;
    for (auto& f : out.fields) {
        f += offset;
    }
    return out;
}

inline pose_soa64_view view_of(const pose_soa64& poses) {
    pose_soa64_view v{};
    for (unsigned f = 0; f < pose_field_count; ++f) {
        v.fields[f] = poses.data(pose_field(f));
    }
    return v;
}

}  // namespace
}  // namespace obbsat::detail
