// What the tests of find_contacts and pair_finder::find_contacts share: the
// options they run with and the scenes they run on.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace contact_scenes {

/// Method exact on `use` with `threads`.
inline obbsat::collide_options exact_on(obbsat::backend use, unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.use = use;
    options.threads = threads;
    return options;
}

/// A seeded scene of `boxes` poses of mixed sizes, about two pairs a box.
inline std::vector<obbsat::rect_pose> scene_of(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.seed = seed;
    spec.boxes = boxes;
    spec.sizes = obbsat::scene_sizes::mixed;
    return obbsat::make_pose_scene(spec);
}

}  // namespace contact_scenes
