// The demo's scene queries: a whole scene of poses to its sorted colliding
// pairs (obbsat/find_pairs.hpp), cold and frame after frame, on 1 and 2
// threads, each stage timed, every row's pairs checked against the others,
// and Box2D's broadphase and narrowphase beside it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace obbsat::cli {

struct scene_demo_settings {
    std::size_t boxes = 1000000;  ///< rectangles per scene
    std::uint64_t seed = 1;
    unsigned reps = 3;            ///< timed runs per row after one warm-up; the median counts
    std::size_t peer_boxes = 100000;  ///< rectangles in the scene Box2D answers
};

/// Prints the section; false (after saying why on stderr) if two rows that
/// must agree gave different pairs.
bool print_scene_queries(const scene_demo_settings& settings);

}  // namespace obbsat::cli
