#include "store/finite_check.hpp"
#include "store/pose_fields.hpp"

#include <obbsat/pose_soa.hpp>

namespace obbsat {

pose_soa::pose_soa(const rect_pose* poses, std::size_t count) {
    reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        push_back(poses[i]);
    }
}

pose_soa::pose_soa(const std::vector<rect_pose>& poses) : pose_soa(poses.data(), poses.size()) {}

pose_soa::pose_soa(const pose_records& poses) {
    reserve(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        detail::append_fields<float>(fields_, poses[i]);
    }
}

void pose_soa::reserve(std::size_t count) {
    for (auto& field : fields_) {
        field.reserve(count);
    }
}

void pose_soa::push_back(const rect_pose& p) {
    require_valid_pose(p, size());
    detail::append_fields<float>(fields_, p);
}

void pose_soa::set(std::size_t index, const rect_pose& p) {
    detail::require_index(index, size());
    require_valid_pose(p, index);
    detail::set_fields<float>(fields_, index, p);
}

void pose_soa::clear() {
    for (auto& field : fields_) {
        field.clear();
    }
}

rect_pose pose_soa::at(std::size_t index) const {
    detail::require_index(index, size());
    return (*this)[index];
}

}  // namespace obbsat
