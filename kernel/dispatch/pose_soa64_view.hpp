// What the kernels see of a pose_soa64: its six double field arrays, as
// dispatch/pose_soa_view.hpp shows a pose_soa's. Plain data, with its helpers
// of internal linkage: the per-ISA kernels read it too (kernel/lanes/README.md).
#pragma once

#include "dispatch/pose_soa_view.hpp"

#include <obbsat/pose_soa64.hpp>
#include <obbsat/rect_pose64.hpp>

#include <cstddef>

namespace obbsat::detail {

using pose_soa64_view = pose_fields_view<double>;

namespace {

/// The pose at `i` of `v`, assembled from the six arrays.
inline rect_pose64 pose64_at(const pose_soa64_view& v, std::size_t i) {
    return rect_pose64{{v.fields[0][i], v.fields[1][i]}, {v.fields[2][i], v.fields[3][i]},
                       {v.fields[4][i], v.fields[5][i]}};
}

inline pose_soa64_view view_of(const pose_soa64& poses) { return fields_view_of<double>(poses); }

}  // namespace
}  // namespace obbsat::detail
