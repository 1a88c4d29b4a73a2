// pose_records64: N rectangles as double poses (see obbsat/rect_pose64.hpp for
// the exact point set), packed in 64-byte records cx, cy, hx, hy, c, s, 0, 0
// (two zero doubles of padding), 64-byte aligned: one pose per cache line.
//
// The store for coordinates float32 would round: UTM metres (3e5 to 6e6 lie
// 0.03 to 0.5 m apart in float32), geographic grids, anything whose gaps are
// below float's spacing at its distance from the origin. Every double is kept
// exactly as given; nothing is rounded to float.
//
// Invariant, checked when a pose is stored, with an error naming the pose and
// the field: every value finite, no half extent negative, the rotation vector
// not (0, 0). Zero half extents (a segment, a point) are valid.
#pragma once

#include <obbsat/rect_pose64.hpp>
#include <obbsat/rect_records.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

class pose_records64 {
public:
    /// Doubles per record: cx, cy, hx, hy, c, s and two zeros.
    static constexpr std::size_t record_doubles = 8;

    pose_records64() = default;
    /// Copies `count` poses; throws invalid_input naming the first bad pose and field.
    pose_records64(const rect_pose64* poses, std::size_t count);
    /// Copies the poses of `poses`; throws invalid_input naming the first bad pose and field.
    explicit pose_records64(const std::vector<rect_pose64>& poses);

    /// The number of poses.
    std::size_t size() const { return records_.size(); }
    /// True iff there are no poses.
    bool empty() const { return records_.empty(); }
    /// Makes room for `count` poses.
    void reserve(std::size_t count) { records_.reserve(count); }
    /// Appends one pose; throws invalid_input naming the field at fault.
    void push_back(const rect_pose64& p);
    /// Replaces pose `index`; throws invalid_input on a bad index or a bad field.
    void set(std::size_t index, const rect_pose64& p);
    /// Removes every pose.
    void clear() { records_.clear(); }

    /// Pose `index`, unchecked: index < size().
    rect_pose64 operator[](std::size_t index) const {
        const record& r = records_[index];
        return rect_pose64{{r.v[0], r.v[1]}, {r.v[2], r.v[3]}, {r.v[4], r.v[5]}};
    }
    /// Pose `index`; throws invalid_input when index >= size().
    rect_pose64 at(std::size_t index) const;
    /// The records, size() of them, record_doubles doubles each, the first on a 64-byte boundary.
    const double* data() const { return records_.empty() ? nullptr : records_.data()->v; }

private:
    struct record {
        double v[record_doubles];
    };
    static_assert(sizeof(record) == 64, "a double pose record is one cache line");
    std::vector<record, cache_line_allocator<record>> records_;
};

/// Throws invalid_input unless `p` is a valid pose: every value finite, no
/// half extent negative, rotation not (0, 0); the message names pose `index`
/// and the field, e.g. "pose 7: half extent hy is -1, negative".
void require_valid_pose(const rect_pose64& p, std::size_t index);

/// Throws as require_valid_pose for the first invalid pose of poses[0, count).
void require_valid_poses(const rect_pose64* poses, std::size_t count);

}  // namespace obbsat
