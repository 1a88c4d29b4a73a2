// Boxes with ids that drift, come, go and change places, for the tests of
// pair_finder's frames whose rows change by id (tests/scene/test_kept_*).
#pragma once

#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat_test {

/// Boxes with ids that drift, and a pool of boxes of the same scene to spawn from.
struct spawning_world {
    std::vector<obbsat::rect_pose> boxes;
    std::vector<std::uint64_t> ids;
    std::vector<obbsat::rect_pose> pool;
    std::uint64_t next = 0;
    obbsat::seeded_random random;

    spawning_world(std::size_t count, std::uint64_t seed) : random(seed) {
        obbsat::pose_scene_spec spec;
        spec.boxes = 2 * count;
        spec.seed = seed;
        spec.sizes = obbsat::scene_sizes::uniform;
        pool = obbsat::make_pose_scene(spec);
        while (boxes.size() < count) {
            spawn();
        }
    }
    void spawn() {
        boxes.push_back(pool[next % pool.size()]);
        ids.push_back(next++);
    }
    void drift() {
        for (obbsat::rect_pose& p : boxes) {
            p.center.x += random.uniform(-0.002f, 0.002f);
            p.center.y += random.uniform(-0.002f, 0.002f);
        }
    }
    /// A spawn frame: drift, `share` of the rows erased at random places and as many appended.
    void spawn_frame(double share) {
        drift();
        const auto churn = static_cast<std::size_t>(share * static_cast<double>(boxes.size()));
        for (std::size_t c = 0; c < churn; ++c) {
            const auto at = static_cast<std::ptrdiff_t>(random.below(boxes.size()));
            boxes.erase(boxes.begin() + at);
            ids.erase(ids.begin() + at);
        }
        for (std::size_t c = 0; c < churn; ++c) {
            spawn();
        }
    }
    /// The last row moves into the hole of row `at`: it changes places against the others.
    void swap_remove(std::size_t at) {
        boxes[at] = boxes.back();
        ids[at] = ids.back();
        boxes.pop_back();
        ids.pop_back();
    }
    /// A swap-remove frame: drift, `share` of the rows removed at random
    /// places by swap_remove and as many appended.
    void swap_remove_frame(double share) {
        drift();
        const auto churn = static_cast<std::size_t>(share * static_cast<double>(boxes.size()));
        for (std::size_t c = 0; c < churn; ++c) {
            swap_remove(static_cast<std::size_t>(random.below(boxes.size())));
        }
        for (std::size_t c = 0; c < churn; ++c) {
            spawn();
        }
    }
};

}  // namespace obbsat_test
