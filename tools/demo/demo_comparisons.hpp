// The comparisons the demo prints under its table: each method on poses
// against its corner counterpart, the conversion of poses to corners, and
// Box2D's narrow phase on the same pairs.
#pragma once

#include "demo/demo_rows.hpp"

#include <obbsat/scene.hpp>

#include <cstdint>
#include <vector>

namespace obbsat::cli {

/// Each method on poses against the corner test it stands in for, both over
/// packed records of the same rectangles on the best backend at 1 thread.
void print_pose_ratios(const std::vector<measured_row>& rows, double pairs);

/// Box2D's narrow phase on the same pairs, and the speedup of the best sat4
/// rows over it; `sat4_seconds` holds the best backend's records rows at 1
/// and 2 threads (0 where not timed).
void print_box2d_comparison(const scene& world, unsigned reps, const std::vector<std::uint8_t>& sat4,
                            const double sat4_seconds[2]);

/// Getting a scene's poses into corners for a corner method: the SIMD
/// conversion of rotation-vector poses (convert_to_corners into the caller's
/// buffer, every backend, each run checked byte for byte against
/// ref::corners_of) against corners built from angles (rect_records::from_poses:
/// cos and sin in double per box, into a new checked store). Returns false
/// after a message when a conversion differs from the reference.
bool print_conversions(const demo_scene& demo, unsigned reps);

}  // namespace obbsat::cli
