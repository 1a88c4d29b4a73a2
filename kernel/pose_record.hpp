// Reading one pose from the 32-byte records of pose_records (cx, cy, hx, hy,
// c, s, 0, 0), for the batch drivers and the scalar path alike. Internal
// linkage, as everything the per-ISA translation units share.
#pragma once

#include <obbsat/pose_records.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>

namespace obbsat::detail {
namespace {

constexpr std::size_t pose_record_floats = pose_records::record_floats;

/// Pose `index` of the records starting at `records`.
inline rect_pose pose_record_at(const float* records, std::size_t index) {
    const float* v = records + pose_record_floats * index;
    return rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}};
}

}  // namespace
}  // namespace obbsat::detail
