// pose_records: N rectangles as poses (see obbsat/rect_pose.hpp for the exact
// point set), packed in 32-byte records cx, cy, hx, hy, c, s, 0, 0 (two zero
// floats of padding), 64-byte aligned: one pose per half cache line, loaded
// whole and transposed in registers, as rect_records is.
//
// This is the store of the methods on poses (local, conservative, exact; see
// obbsat/method.hpp). It holds a third of the data of corner records' work:
// a pair is decided from two centers, four half extents and two rotations.
//
// Invariant, checked when a pose is stored, with an error naming the pose and
// the field: every value finite, no half extent negative, the rotation vector
// not (0, 0). Zero half extents (a segment, a point) are valid.
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

class pose_records {
public:
    /// Floats per record: cx, cy, hx, hy, c, s and two zeros.
    static constexpr std::size_t record_floats = 8;

    pose_records() = default;
    /// Copies `count` poses; throws invalid_input naming the first bad pose and field.
    pose_records(const rect_pose* poses, std::size_t count);
    /// Copies the poses of `poses`; throws invalid_input naming the first bad pose and field.
    explicit pose_records(const std::vector<rect_pose>& poses);

    /// Poses with an angle, converted by rect_pose_of(const pose&); throws as above.
    static pose_records from_angles(const pose* poses, std::size_t count);
    /// Poses with an angle, converted by rect_pose_of(const pose&); throws as above.
    static pose_records from_angles(const std::vector<pose>& poses);
    /// Corner rectangles, converted by rect_pose_of(const rect&); throws as above.
    static pose_records from_corners(const rect_records& rects);

    /// The number of poses.
    std::size_t size() const { return records_.size(); }
    /// True iff there are no poses.
    bool empty() const { return records_.empty(); }
    /// Makes room for `count` poses.
    void reserve(std::size_t count) { records_.reserve(count); }
    /// Appends one pose; throws invalid_input naming the field at fault.
    void push_back(const rect_pose& p);
    /// Replaces pose `index`; throws invalid_input on a bad index or a bad field.
    void set(std::size_t index, const rect_pose& p);
    /// Removes every pose.
    void clear() { records_.clear(); }

    /// Pose `index`, unchecked: index < size().
    rect_pose operator[](std::size_t index) const {
        const record& r = records_[index];
        return rect_pose{{r.v[0], r.v[1]}, {r.v[2], r.v[3]}, {r.v[4], r.v[5]}};
    }
    /// Pose `index`; throws invalid_input when index >= size().
    rect_pose at(std::size_t index) const;
    /// The records, size() of them, record_floats floats each, the first on a 64-byte boundary.
    const float* data() const { return records_.empty() ? nullptr : records_.data()->v; }

private:
    struct record {
        float v[record_floats];
    };
    static_assert(sizeof(record) == 32, "a pose record is 32 bytes");
    std::vector<record, cache_line_allocator<record>> records_;
};

/// Throws invalid_input unless `p` is a valid pose: every value finite, no
/// half extent negative, rotation not (0, 0); the message names pose `index`
/// and the field, e.g. "pose 7: half extent hy is -1".
void require_valid_pose(const rect_pose& p, std::size_t index);

/// Throws as require_valid_pose for the first invalid pose of poses[0, count);
/// one branch-free pass when every pose is valid.
void require_valid_poses(const rect_pose* poses, std::size_t count);

}  // namespace obbsat
