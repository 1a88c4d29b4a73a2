// pose_soa: N poses (see obbsat/rect_pose.hpp for the exact point set) as six
// float arrays, cx, cy, hx, hy, c, s, each 64-byte aligned: the store for
// streaming batches of poses (collide_stream: A[i] against B[i]), which the
// kernels read one vector per field with no transposition. pose_records
// suits pair lists (one half cache line per pose fetched at random).
//
// Invariant, checked when a pose is stored, as in pose_records: every value
// finite, no half extent negative, the rotation vector not (0, 0).
#pragma once

#include <obbsat/pose_records.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

/// The six fields of a pose, in the order of pose_soa's arrays and of pose_records' records.
enum class pose_field : unsigned { cx, cy, hx, hy, c, s };
inline constexpr unsigned pose_field_count = 6;

class pose_soa {
public:
    pose_soa() = default;
    /// Copies `count` poses; throws invalid_input naming the first bad pose and field.
    pose_soa(const rect_pose* poses, std::size_t count);
    /// Copies the poses of `poses`; throws invalid_input naming the first bad pose and field.
    explicit pose_soa(const std::vector<rect_pose>& poses);
    /// Copies the poses of a record store (already valid).
    explicit pose_soa(const pose_records& poses);

    /// The number of poses.
    std::size_t size() const { return fields_[0].size(); }
    /// True iff there are no poses.
    bool empty() const { return fields_[0].empty(); }
    /// Makes room for `count` poses.
    void reserve(std::size_t count);
    /// Appends one pose; throws invalid_input naming the field at fault.
    void push_back(const rect_pose& p);
    /// Replaces pose `index`; throws invalid_input on a bad index or a bad field.
    void set(std::size_t index, const rect_pose& p);
    /// Removes every pose.
    void clear();

    /// Pose `index`, unchecked: index < size().
    rect_pose operator[](std::size_t index) const {
        return rect_pose{{fields_[0][index], fields_[1][index]},
                         {fields_[2][index], fields_[3][index]},
                         {fields_[4][index], fields_[5][index]}};
    }
    /// Pose `index`; throws invalid_input when index >= size().
    rect_pose at(std::size_t index) const;
    /// The array of one field: size() values, the first on a 64-byte boundary.
    const float* data(pose_field f) const { return fields_[static_cast<unsigned>(f)].data(); }

private:
    std::vector<float, cache_line_allocator<float>> fields_[pose_field_count];
};

}  // namespace obbsat
