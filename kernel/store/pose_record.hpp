// Reading one pose from the 32-byte records of pose_records (cx, cy, hx, hy,
// c, s, 0, 0), for the batch drivers and the scalar path alike. Internal
// linkage, as everything the per-ISA translation units share
// (kernel/lanes/README.md).
#pragma once

#include <obbsat/pose_records.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>
#include <cstring>

namespace obbsat::detail {
namespace {

constexpr std::size_t pose_record_floats = pose_records::record_floats;

/// Pose `index` of the records starting at `records`.
inline rect_pose pose_record_at(const float* records, std::size_t index) {
    const float* v = records + pose_record_floats * index;
    return rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}};
}

/// Writes the six floats of a pose row (cx, cy, hx, hy, c, s) as the record
/// at `record`, its two last floats zero. Straight from the row: a local
/// copy reloaded whole would stall on store forwarding.
inline void widen_pose_row(float* record, const float* row) {
    std::memcpy(record, row, 6 * sizeof(float));
    std::memset(record + 6, 0, (pose_record_floats - 6) * sizeof(float));
}

}  // namespace
}  // namespace obbsat::detail
