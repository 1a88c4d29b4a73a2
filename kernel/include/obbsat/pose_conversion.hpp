// Poses to corners, in SIMD: for users who hold poses and want a corner
// method (sat4, sat4_centered, sat4_double). Every backend produces exactly
// the corners of the scalar reference obbsat::ref::corners_of(const rect_pose&)
// (obbsat/ref/pose_corners.hpp states the float operations).
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>

namespace obbsat {

/// out[i] = ref::corners_of(poses[i]) for i < poses.size(), on backend `use`;
/// returns the backend that ran. `out` holds poses.size() rects. A corner may
/// overflow to an infinity for a pose near the float range's end; see
/// corner_records_of for the checked form.
backend convert_to_corners(const pose_records& poses, rect* out, backend use = backend::automatic);

/// The corner records of `poses`, converted as convert_to_corners does.
/// Throws invalid_input naming the first pose whose corners are not finite,
/// unsupported_backend as the batch calls do.
rect_records corner_records_of(const pose_records& poses, backend use = backend::automatic);

}  // namespace obbsat
