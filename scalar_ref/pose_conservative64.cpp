#include <obbsat/ref/pose_conservative64.hpp>

#include <cmath>
#include <limits>

namespace obbsat::ref {

void pose_gaps(const pose_axes64& axes, double gap[4]) {
    for (int k = 0; k < 4; ++k) {
        gap[k] = std::fabs(axes.offset[k]) - axes.reach[k];
    }
}

pose_margins64 margins_of(const rect_pose64& a, const rect_pose64& b, const pose_axes64& axes) {
    const double D = std::fabs(axes.dx) + std::fabs(axes.dy);
    const double Ra = std::fmax(std::fabs(a.rotation.x), std::fabs(a.rotation.y));
    const double Rb = std::fmax(std::fabs(b.rotation.x), std::fabs(b.rotation.y));
    const double Ha = a.half_extents.x + a.half_extents.y;
    const double Hb = b.half_extents.x + b.half_extents.y;
    const double T = (D + (Ra * Ha)) + (Rb * Hb);
    const double Sa = Ra * T;
    const double Sb = Rb * T;
    const bool in_range = Ra >= 0x1p-500 && Ra <= 0x1p500 && Rb >= 0x1p-500 && Rb <= 0x1p500;
    if (Sa <= 0x1p1000 && Sb <= 0x1p1000 && in_range) {
        return pose_margins64{(0x1p-48 * Sa) + 0x1p-1000, (0x1p-48 * Sb) + 0x1p-1000};
    }
    const double none = std::numeric_limits<double>::infinity();
    return pose_margins64{none, none};
}

namespace {

/// The margin of axis k: A's for axes 0 and 1, B's for 2 and 3.
double margin_of_axis(const pose_margins64& m, int k) { return k < 2 ? m.a : m.b; }

}  // namespace

bool conservative(const rect_pose64& a, const rect_pose64& b) {
    const pose_axes64 axes = local_axes(a, b);
    const pose_margins64 margins = margins_of(a, b, axes);
    double gap[4];
    pose_gaps(axes, gap);
    for (int k = 0; k < 4; ++k) {
        if (gap[k] > margin_of_axis(margins, k)) {
            return false;
        }
    }
    return true;
}

certified_verdict certify(const rect_pose64& a, const rect_pose64& b) {
    const pose_axes64 axes = local_axes(a, b);
    const pose_margins64 margins = margins_of(a, b, axes);
    double gap[4];
    pose_gaps(axes, gap);
    bool apart = false;
    bool overlapping = true;
    for (int k = 0; k < 4; ++k) {
        const double margin = margin_of_axis(margins, k);
        apart = apart || gap[k] > margin;
        overlapping = overlapping && gap[k] < -margin;
    }
    return certified_verdict{apart, overlapping && !apart};
}

}  // namespace obbsat::ref
