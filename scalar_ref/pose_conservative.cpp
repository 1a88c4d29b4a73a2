#include <obbsat/ref/pose_conservative.hpp>

#include <cmath>
#include <limits>

namespace obbsat::ref {

void pose_gaps(const pose_axes& axes, float gap[4]) {
    for (int k = 0; k < 4; ++k) {
        gap[k] = std::fabs(axes.offset[k]) - axes.reach[k];
    }
}

float pose_margin(const rect_pose& a, const rect_pose& b, const pose_axes& axes) {
    const float D = std::fabs(axes.dx) + std::fabs(axes.dy);
    const float R = std::fmax(std::fmax(std::fabs(a.rotation.x), std::fabs(a.rotation.y)),
                              std::fmax(std::fabs(b.rotation.x), std::fabs(b.rotation.y)));
    const float H = ((a.half_extents.x + a.half_extents.y) + b.half_extents.x) + b.half_extents.y;
    const float S = (D * R) + ((R * R) * H);
    if (S <= 0x1p100f && R >= 0x1p-40f && R <= 0x1p62f) {
        return (0x1p-19f * S) + 0x1p-140f;
    }
    return std::numeric_limits<float>::infinity();
}

bool conservative(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    const float margin = pose_margin(a, b, axes);
    float gap[4];
    pose_gaps(axes, gap);
    for (int k = 0; k < 4; ++k) {
        if (gap[k] > margin) {
            return false;
        }
    }
    return true;
}

certified_verdict certify(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    const float margin = pose_margin(a, b, axes);
    float gap[4];
    pose_gaps(axes, gap);
    bool apart = false;
    bool overlapping = true;
    for (int k = 0; k < 4; ++k) {
        apart = apart || gap[k] > margin;
        overlapping = overlapping && gap[k] < -margin;
    }
    return certified_verdict{apart, overlapping && !apart};
}

}  // namespace obbsat::ref
