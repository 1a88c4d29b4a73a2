#include "store/finite_check.hpp"
#include "store/pose_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_records64.hpp>

#include <cmath>

namespace obbsat {

namespace {

// Branch-free, so that a batch checks at copy speed; require_valid_pose names
// the offender once a pass found one.
bool valid_pose(const rect_pose64& p) {
    const bool finite = std::isfinite(p.center.x) & std::isfinite(p.center.y) & std::isfinite(p.half_extents.x) &
                        std::isfinite(p.half_extents.y) & std::isfinite(p.rotation.x) & std::isfinite(p.rotation.y);
    return finite & !(p.half_extents.x < 0.0) & !(p.half_extents.y < 0.0) &
           !((p.rotation.x == 0.0) & (p.rotation.y == 0.0));
}

}  // namespace

void require_valid_pose(const rect_pose64& p, std::size_t index) { detail::require_valid_pose_fields(p, index); }

void require_valid_poses(const rect_pose64* poses, std::size_t count) {
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

pose_records64::pose_records64(const rect_pose64* poses, std::size_t count) {
    // Checked before anything is copied: a bad batch leaves nothing half-stored.
    require_valid_poses(poses, count);
    records_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const rect_pose64& p = poses[i];
        records_[i] = record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                              p.rotation.y, 0.0, 0.0}};
    }
}

pose_records64::pose_records64(const std::vector<rect_pose64>& poses) : pose_records64(poses.data(), poses.size()) {}

void pose_records64::push_back(const rect_pose64& p) {
    require_valid_pose(p, records_.size());
    records_.push_back(record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                               p.rotation.y, 0.0, 0.0}});
}

void pose_records64::set(std::size_t index, const rect_pose64& p) {
    detail::require_index(index, records_.size());
    require_valid_pose(p, index);
    records_[index] = record{{p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                              p.rotation.y, 0.0, 0.0}};
}

rect_pose64 pose_records64::at(std::size_t index) const {
    detail::require_index(index, records_.size());
    return (*this)[index];
}

}  // namespace obbsat
