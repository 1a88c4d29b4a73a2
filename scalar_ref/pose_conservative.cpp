// Methods conservative and exact's certified fast path on float and on double
// poses: one set of steps (pose_steps.hpp), the operations and the proven
// margins stated in obbsat/ref/pose_conservative.hpp and pose_conservative64.hpp.
#include "pose_steps.hpp"

#include <obbsat/ref/pose_conservative.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

namespace obbsat::ref {

namespace {

/// float32: margins proven for rotations of length 2^-40 to 2^62 and S up to 2^100.
constexpr pose_steps::margin_limits<float> float_limits{0x1p-40f, 0x1p62f, 0x1p100f, 0x1p-19f, 0x1p-140f};

/// double: margins proven for rotations of length 2^-500 to 2^500 and S up to 2^1000.
constexpr pose_steps::margin_limits<double> double_limits{0x1p-500, 0x1p500, 0x1p1000, 0x1p-48, 0x1p-1000};

}  // namespace

void pose_gaps(const pose_axes& axes, float gap[4]) { pose_steps::gaps_of(axes, gap); }

void pose_gaps(const pose_axes64& axes, double gap[4]) { pose_steps::gaps_of(axes, gap); }

pose_margins margins_of(const rect_pose& a, const rect_pose& b, const pose_axes& axes) {
    return pose_steps::margins_of<pose_margins>(a, b, axes, float_limits);
}

pose_margins64 margins_of(const rect_pose64& a, const rect_pose64& b, const pose_axes64& axes) {
    return pose_steps::margins_of<pose_margins64>(a, b, axes, double_limits);
}

bool conservative(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    return pose_steps::none_apart<float>(axes, margins_of(a, b, axes));
}

bool conservative(const rect_pose64& a, const rect_pose64& b) {
    const pose_axes64 axes = local_axes(a, b);
    return pose_steps::none_apart<double>(axes, margins_of(a, b, axes));
}

certified_verdict certify(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    return pose_steps::certify_from<float>(axes, margins_of(a, b, axes));
}

certified_verdict certify(const rect_pose64& a, const rect_pose64& b) {
    const pose_axes64 axes = local_axes(a, b);
    return pose_steps::certify_from<double>(axes, margins_of(a, b, axes));
}

}  // namespace obbsat::ref
