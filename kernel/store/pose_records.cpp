#include "store/finite_check.hpp"
#include "store/pose_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_records.hpp>

#include <cmath>
#include <cstring>

namespace obbsat {

void require_valid_pose(const rect_pose& p, std::size_t index) { detail::require_valid_pose_fields(p, index); }

namespace {

/// True iff `p` is valid, without branches, so that a batch checks at copy speed.
bool valid_pose(const rect_pose& p) {
    float row[6];
    static_assert(sizeof row == sizeof p, "a rect_pose is cx, cy, hx, hy, c, s");
    std::memcpy(row, &p, sizeof row);
    return detail::valid_pose_row(row);
}

}  // namespace

void require_valid_poses(const rect_pose* poses, std::size_t count) {
    bool all_valid = true;
    for (std::size_t i = 0; i < count; ++i) {
        all_valid &= valid_pose(poses[i]);
    }
    if (!all_valid) {
        for (std::size_t i = 0; i < count; ++i) {
            require_valid_pose(poses[i], i);
        }
    }
}

pose_records::pose_records(const rect_pose* poses, std::size_t count) {
    // One pass copies and checks; only a batch with a bad pose is searched
    // again, to name the first one.
    records_.resize(count);
    bool all_valid = true;
    for (std::size_t i = 0; i < count; ++i) {
        const rect_pose& p = poses[i];
        records_[i] = record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                              p.rotation.y, 0.0f, 0.0f}};
        all_valid &= valid_pose(p);
    }
    if (!all_valid) {
        for (std::size_t i = 0; i < count; ++i) {
            require_valid_pose(poses[i], i);
        }
    }
}

pose_records::pose_records(const std::vector<rect_pose>& poses) : pose_records(poses.data(), poses.size()) {}

pose_records pose_records::from_angles(const pose* poses, std::size_t count) {
    pose_records out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (!std::isfinite(poses[i].angle)) {
            detail::refuse_pose(i, "angle is " + detail::shown_field(poses[i].angle) + ", not a finite number");
        }
        out.push_back(rect_pose_of(poses[i]));
    }
    return out;
}

pose_records pose_records::from_angles(const std::vector<pose>& poses) {
    return from_angles(poses.data(), poses.size());
}

pose_records pose_records::from_corners(const rect_records& rects) {
    pose_records out;
    out.reserve(rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        out.push_back(rect_pose_of(rects[i]));
    }
    return out;
}

void pose_records::push_back(const rect_pose& p) {
    require_valid_pose(p, records_.size());
    records_.push_back(record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                               p.rotation.y, 0.0f, 0.0f}});
}

void pose_records::set(std::size_t index, const rect_pose& p) {
    detail::require_index(index, records_.size());
    require_valid_pose(p, index);
    records_[index] = record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                              p.rotation.y, 0.0f, 0.0f}};
}

rect_pose pose_records::at(std::size_t index) const {
    detail::require_index(index, records_.size());
    return (*this)[index];
}

}  // namespace obbsat
