#include "store/finite_check.hpp"
#include "store/pose_fields.hpp"

#include <obbsat/pose_soa64.hpp>

namespace obbsat {

pose_soa64::pose_soa64(const rect_pose64* poses, std::size_t count) {
    // Checked before anything is copied: a bad batch leaves nothing half-stored.
    require_valid_poses(poses, count);
    reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        append(poses[i]);
    }
}

pose_soa64::pose_soa64(const std::vector<rect_pose64>& poses) : pose_soa64(poses.data(), poses.size()) {}

pose_soa64::pose_soa64(const pose_records64& poses) {
    reserve(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        append(poses[i]);
    }
}

void pose_soa64::reserve(std::size_t count) {
    for (auto& field : fields_) {
        field.reserve(count);
    }
}

void pose_soa64::append(const rect_pose64& p) {
    detail::append_fields<double>(fields_, p);
}

void pose_soa64::push_back(const rect_pose64& p) {
    require_valid_pose(p, size());
    append(p);
}

void pose_soa64::set(std::size_t index, const rect_pose64& p) {
    detail::require_index(index, size());
    require_valid_pose(p, index);
    detail::set_fields<double>(fields_, index, p);
}

void pose_soa64::clear() {
    for (auto& field : fields_) {
        field.clear();
    }
}

rect_pose64 pose_soa64::at(std::size_t index) const {
    detail::require_index(index, size());
    return (*this)[index];
}

}  // namespace obbsat
