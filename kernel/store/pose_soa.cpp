#include "store/finite_check.hpp"

#include <obbsat/pose_soa.hpp>

namespace obbsat {

namespace {

void fields_of(const rect_pose& p, float out[pose_field_count]) {
    out[0] = p.center.x;
    out[1] = p.center.y;
    out[2] = p.half_extents.x;
    out[3] = p.half_extents.y;
    out[4] = p.rotation.x;
    out[5] = p.rotation.y;
}

}  // namespace

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
        float values[pose_field_count];
        fields_of(poses[i], values);
        for (unsigned f = 0; f < pose_field_count; ++f) {
            fields_[f].push_back(values[f]);
        }
    }
}

void pose_soa::reserve(std::size_t count) {
    for (auto& field : fields_) {
        field.reserve(count);
    }
}

void pose_soa::push_back(const rect_pose& p) {
    require_valid_pose(p, size());
    float values[pose_field_count];
    fields_of(p, values);
    for (unsigned f = 0; f < pose_field_count; ++f) {
        fields_[f].push_back(values[f]);
    }
}

void pose_soa::set(std::size_t index, const rect_pose& p) {
    detail::require_index(index, size());
    require_valid_pose(p, index);
    float values[pose_field_count];
    fields_of(p, values);
    for (unsigned f = 0; f < pose_field_count; ++f) {
        fields_[f][index] = values[f];
    }
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
