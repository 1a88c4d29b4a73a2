// What the kernels see of a pose_soa: six field arrays, shifted as a batch is
// split over threads.
#pragma once

#include <obbsat/pose_soa.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>

namespace obbsat::detail {

struct pose_soa_view {
    const float* fields[pose_field_count];  // cx, cy, hx, hy, c, s

    /// The pose at `i`, assembled from the six arrays.
    rect_pose at(std::size_t i) const {
        return rect_pose{{fields[0][i], fields[1][i]}, {fields[2][i], fields[3][i]}, {fields[4][i], fields[5][i]}};
    }

    /// The same arrays starting `offset` poses later.
    pose_soa_view shifted(std::size_t offset) const {
        pose_soa_view out = *this;
        for (auto& f : out.fields) {
            f += offset;
        }
        return out;
    }
};

inline pose_soa_view view_of(const pose_soa& poses) {
    pose_soa_view v{};
    for (unsigned f = 0; f < pose_field_count; ++f) {
        v.fields[f] = poses.data(pose_field(f));
    }
    return v;
}

}  // namespace obbsat::detail
