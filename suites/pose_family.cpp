#include <obbsat/suites/pose_family.hpp>

#include <obbsat/error.hpp>

#include <string>

namespace obbsat::suites {

const char* pose_family_name(pose_family f) {
    switch (f) {
        case pose_family::near: return "near";
        case pose_family::contact: return "contact";
        case pose_family::integer_contact: return "integer_contact";
        case pose_family::far: return "far";
        case pose_family::rotation_scale: return "rotation_scale";
        case pose_family::zero_extents: return "zero_extents";
        case pose_family::slivers: return "slivers";
        case pose_family::near_parallel: return "near_parallel";
        case pose_family::tiny: return "tiny";
        case pose_family::huge: return "huge";
    }
    return "unknown";
}

const std::vector<pose_family>& all_pose_families() {
    static const std::vector<pose_family> families = {
        pose_family::near,         pose_family::contact, pose_family::integer_contact,
        pose_family::far,          pose_family::rotation_scale, pose_family::zero_extents,
        pose_family::slivers,      pose_family::near_parallel,  pose_family::tiny,
        pose_family::huge};
    return families;
}

pose_family parse_pose_family(std::string_view name) {
    std::string known;
    for (const pose_family f : all_pose_families()) {
        if (name == pose_family_name(f)) {
            return f;
        }
        known += known.empty() ? "" : ", ";
        known += pose_family_name(f);
    }
    throw invalid_input("unknown pose family '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace obbsat::suites
