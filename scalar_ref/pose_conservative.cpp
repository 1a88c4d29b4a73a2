#include <obbsat/ref/pose_conservative.hpp>

#include <cmath>
#include <limits>

namespace obbsat::ref {

void pose_gaps(const pose_axes& axes, float gap[4]) {
    for (int k = 0; k < 4; ++k) {
        gap[k] = std::fabs(axes.offset[k]) - axes.reach[k];
    }
}

pose_margins margins_of(const rect_pose& a, const rect_pose& b, const pose_axes& axes) {
    const float D = std::fabs(axes.dx) + std::fabs(axes.dy);
    const float Ra = std::fmax(std::fabs(a.rotation.x), std::fabs(a.rotation.y));
    const float Rb = std::fmax(std::fabs(b.rotation.x), std::fabs(b.rotation.y));
    const float Ha = a.half_extents.x + a.half_extents.y;
    const float Hb = b.half_extents.x + b.half_extents.y;
    const float T = (D + (Ra * Ha)) + (Rb * Hb);
    const float Sa = Ra * T;
    const float Sb = Rb * T;
    const bool in_range = Ra >= 0x1p-40f && Ra <= 0x1p62f && Rb >= 0x1p-40f && Rb <= 0x1p62f;
    if (Sa <= 0x1p100f && Sb <= 0x1p100f && in_range) {
        return pose_margins{(0x1p-19f * Sa) + 0x1p-140f, (0x1p-19f * Sb) + 0x1p-140f};
    }
    const float none = std::numeric_limits<float>::infinity();
    return pose_margins{none, none};
}

namespace {

/// The margin of axis k: A's for axes 0 and 1, B's for 2 and 3.
float margin_of_axis(const pose_margins& m, int k) { return k < 2 ? m.a : m.b; }

}  // namespace

bool conservative(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    const pose_margins margins = margins_of(a, b, axes);
    float gap[4];
    pose_gaps(axes, gap);
    for (int k = 0; k < 4; ++k) {
        if (gap[k] > margin_of_axis(margins, k)) {
            return false;
        }
    }
    return true;
}

certified_verdict certify(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    const pose_margins margins = margins_of(a, b, axes);
    float gap[4];
    pose_gaps(axes, gap);
    bool apart = false;
    bool overlapping = true;
    for (int k = 0; k < 4; ++k) {
        const float margin = margin_of_axis(margins, k);
        apart = apart || gap[k] > margin;
        overlapping = overlapping && gap[k] < -margin;
    }
    return certified_verdict{apart, overlapping && !apart};
}

}  // namespace obbsat::ref
