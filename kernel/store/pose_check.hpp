// The check every pose store makes of a pose, written once over the pose type
// (obbsat::rect_pose in float, obbsat::rect_pose64 in double): each field
// finite, half extents non-negative, rotation other than (0, 0). The error
// names the pose's index, the field and its value (a double with all 17
// significant digits, so that the value named is the value given).
#pragma once

#include <obbsat/error.hpp>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <type_traits>

namespace obbsat::detail {

template <class Real>
std::string shown_field(Real value) {
    std::ostringstream out;
    if (std::is_same<Real, double>::value) {
        out.precision(17);
    }
    out << value;
    return out.str();
}

[[noreturn]] inline void refuse_pose(std::size_t index, const std::string& what) {
    throw invalid_input("pose " + std::to_string(index) + ": " + what);
}

/// Throws invalid_input naming pose `index` and its first bad field.
template <class Pose>
void require_valid_pose_fields(const Pose& p, std::size_t index) {
    using Real = decltype(p.center.x);
    const struct {
        const char* name;
        Real value;
    } fields[] = {{"cx", p.center.x},       {"cy", p.center.y},  {"hx", p.half_extents.x},
                  {"hy", p.half_extents.y}, {"c", p.rotation.x}, {"s", p.rotation.y}};
    for (const auto& f : fields) {
        if (!std::isfinite(f.value)) {
            refuse_pose(index, std::string(f.name) + " is " + shown_field(f.value) + ", not a finite number");
        }
    }
    if (p.half_extents.x < Real(0)) {
        refuse_pose(index, "half extent hx is " + shown_field(p.half_extents.x) + ", negative");
    }
    if (p.half_extents.y < Real(0)) {
        refuse_pose(index, "half extent hy is " + shown_field(p.half_extents.y) + ", negative");
    }
    if (p.rotation.x == Real(0) && p.rotation.y == Real(0)) {
        refuse_pose(index, "rotation vector (c, s) is (0, 0)");
    }
}

}  // namespace obbsat::detail
