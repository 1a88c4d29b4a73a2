#include "dispatch/backend_registry.hpp"
#include "store/finite_check.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_conversion.hpp>

#include <cmath>
#include <vector>

namespace obbsat {

backend convert_to_corners(const pose_records& poses, rect* out, backend use) {
    const backend ran = resolve_backend(use);
    if (!poses.empty()) {
        detail::kernels_for(ran).pose_corners(poses.data(), poses.size(), out);
    }
    return ran;
}

rect_records corner_records_of(const pose_records& poses, backend use) {
    std::vector<rect> corners(poses.size());
    convert_to_corners(poses, corners.data(), use);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const rect& r = corners[i];
        const float values[] = {r.ul.x, r.ul.y, r.ur.x, r.ur.y, r.lr.x, r.lr.y, r.ll.x, r.ll.y};
        for (const float v : values) {
            if (!std::isfinite(v)) {
                throw invalid_input("pose " + std::to_string(i) +
                                    ": its corners overflow the float range (a corner is not finite)");
            }
        }
    }
    return rect_records(corners);
}

}  // namespace obbsat
