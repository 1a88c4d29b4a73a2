// Method local on float and on double poses: one set of steps
// (pose_steps.hpp), the operations stated in obbsat/ref/local.hpp and local64.hpp.
#include "pose_steps.hpp"

#include <obbsat/ref/local.hpp>
#include <obbsat/ref/local64.hpp>

namespace obbsat::ref {

pose_axes local_axes(const rect_pose& a, const rect_pose& b) { return pose_steps::axes_of<pose_axes>(a, b); }

pose_axes64 local_axes(const rect_pose64& a, const rect_pose64& b) { return pose_steps::axes_of<pose_axes64>(a, b); }

bool shows_overlap(const pose_axes& axes, int k) { return pose_steps::shows_overlap(axes, k); }

bool shows_overlap(const pose_axes64& axes, int k) { return pose_steps::shows_overlap(axes, k); }

bool local(const rect_pose& a, const rect_pose& b) { return pose_steps::all_show_overlap(local_axes(a, b)); }

bool local(const rect_pose64& a, const rect_pose64& b) { return pose_steps::all_show_overlap(local_axes(a, b)); }

}  // namespace obbsat::ref
