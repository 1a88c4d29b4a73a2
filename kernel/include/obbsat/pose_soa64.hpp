// pose_soa64: N double poses (see obbsat/rect_pose64.hpp for the exact point
// set) as six double arrays, cx, cy, hx, hy, c, s, each 64-byte aligned: the
// double counterpart of pose_soa, the store for streaming batches of double
// poses (collide_stream: A[i] against B[i]), which the kernels read one vector
// per field with no transposition. pose_records64 suits pair lists (one cache
// line per pose fetched at random).
//
// Every double is kept exactly as given. Invariant, checked when a pose is
// stored, as in pose_records64: every value finite, no half extent negative,
// the rotation vector not (0, 0); an error names the pose and the field.
#pragma once

#include <obbsat/pose_records64.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

class pose_soa64 {
public:
    pose_soa64() = default;
    /// Copies `count` poses; throws invalid_input naming the first bad pose and field (nothing stored).
    pose_soa64(const rect_pose64* poses, std::size_t count);
    /// Copies the poses of `poses`; throws invalid_input naming the first bad pose and field.
    explicit pose_soa64(const std::vector<rect_pose64>& poses);
    /// Copies the poses of a record store (already valid).
    explicit pose_soa64(const pose_records64& poses);

    /// The number of poses.
    std::size_t size() const { return fields_[0].size(); }
    /// True iff there are no poses.
    bool empty() const { return fields_[0].empty(); }
    /// Makes room for `count` poses.
    void reserve(std::size_t count);
    /// Appends one pose; throws invalid_input naming the field at fault.
    void push_back(const rect_pose64& p);
    /// Replaces pose `index`; throws invalid_input on a bad index or a bad field.
    void set(std::size_t index, const rect_pose64& p);
    /// Removes every pose.
    void clear();

    /// Pose `index`, unchecked: index < size().
    rect_pose64 operator[](std::size_t index) const {
        return rect_pose64{{fields_[0][index], fields_[1][index]},
                           {fields_[2][index], fields_[3][index]},
                           {fields_[4][index], fields_[5][index]}};
    }
    /// Pose `index`; throws invalid_input when index >= size().
    rect_pose64 at(std::size_t index) const;
    /// The array of one field: size() values, the first on a 64-byte boundary.
    const double* data(pose_field f) const { return fields_[static_cast<unsigned>(f)].data(); }

private:
    /// Appends `p`, already checked.
    void append(const rect_pose64& p);

    std::vector<double, cache_line_allocator<double>> fields_[pose_field_count];
};

}  // namespace obbsat
