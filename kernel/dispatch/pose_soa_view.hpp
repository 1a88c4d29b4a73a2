// What the kernels see of a pose store of arrays, pose_soa (float) or
// pose_soa64 (double, dispatch/pose_soa64_view.hpp): six field arrays,
// shifted as a batch is split over threads. Plain data, with its helpers of
// internal linkage: the per-ISA kernels read it too (kernel/lanes/README.md).
#pragma once

#include <obbsat/pose_soa.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>

namespace obbsat::detail {

/// The six field arrays of a pose store of Real.
template <class Real>
struct pose_fields_view {
    const Real* fields[pose_field_count];  // cx, cy, hx, hy, c, s
};

using pose_soa_view = pose_fields_view<float>;

namespace {

/// The pose at `i` of `v`, assembled from the six arrays.
inline rect_pose pose_at(const pose_soa_view& v, std::size_t i) {
    return rect_pose{{v.fields[0][i], v.fields[1][i]}, {v.fields[2][i], v.fields[3][i]}, {v.fields[4][i], v.fields[5][i]}};
}

/// The arrays of `v` starting `offset` poses later.
template <class Real>
inline pose_fields_view<Real> shifted(const pose_fields_view<Real>& v, std::size_t offset) {
    pose_fields_view<Real> out = v;
    for (auto& f : out.fields) {
        f += offset;
    }
    return out;
}

/// The arrays of a store (pose_soa or pose_soa64) holding Real.
template <class Real, class Store>
inline pose_fields_view<Real> fields_view_of(const Store& poses) {
    pose_fields_view<Real> v{};
    for (unsigned f = 0; f < pose_field_count; ++f) {
        v.fields[f] = poses.data(pose_field(f));
    }
    return v;
}

inline pose_soa_view view_of(const pose_soa& poses) { return fields_view_of<float>(poses); }

}  // namespace
}  // namespace obbsat::detail
