// Seeded whole scenes of poses, for the scene queries' demo, tests and
// benchmarks: rectangles at uniformly random positions and orientations in a
// square whose side gives about `pairs_per_box` colliding pairs per rectangle.
//
// Sizes: uniform, half extents uniform in [0.5, 1.5]; mixed, a size
// log-uniform over two decades, [0.2, 20], with an aspect ratio uniform in
// [0.3, 1]. The side comes from the mean Minkowski sum of two rectangles at
// random orientations (2·area + perimeter²/2π), so the density is as asked
// up to boundary effects and sampling.
//
// Generation uses only IEEE basic arithmetic (orientations from the rational
// parametrisation of the unit circle, the log-uniform sizes from a fixed
// series, the side from std::sqrt, which IEEE rounds correctly), so a spec
// gives the same bytes on every machine.
#pragma once

#include <obbsat/rect_pose.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace obbsat {

/// How the sizes of a scene's rectangles are spread.
enum class scene_sizes { uniform, mixed };

/// "uniform" or "mixed".
const char* scene_sizes_name(scene_sizes sizes);

/// The sizes called `name`, or nothing.
std::optional<scene_sizes> parse_scene_sizes(std::string_view name);

struct pose_scene_spec {
    std::uint64_t seed = 1;
    std::size_t boxes = 100000;
    scene_sizes sizes = scene_sizes::uniform;
    double pairs_per_box = 2.0;  ///< colliding pairs per rectangle wanted, about
    double origin_x = 0;         ///< the scene's lower left corner
    double origin_y = 0;
};

/// The poses of `spec`: deterministic for a given spec.
std::vector<rect_pose> make_pose_scene(const pose_scene_spec& spec);

/// The side of the square the scene of `spec` fills.
double pose_scene_side(const pose_scene_spec& spec);

}  // namespace obbsat
