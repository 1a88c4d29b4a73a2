// A pair list that mixes what a broadphase hands a narrowphase with noise: the
// colliding pairs of a pose scene (exact, in find_pairs' order, so runs of one
// first index) with one pair drawn at random after every third of them.
#pragma once

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/scene.hpp>

#include <cstdint>
#include <vector>

namespace obbsat::test_support {

inline std::vector<pair_index> colliding_pairs_mixed_with_random(const pose_records& poses, std::uint64_t seed) {
    collide_options options;
    options.test = method::exact;
    const std::vector<pair_index> colliding = find_pairs(poses, options);
    seeded_random random(seed);
    const auto boxes = static_cast<std::uint32_t>(poses.size());
    std::vector<pair_index> pairs;
    for (std::size_t i = 0; i < colliding.size(); ++i) {
        pairs.push_back(colliding[i]);
        if (i % 3 == 0) {
            const auto a = static_cast<std::uint32_t>(random.below(boxes));
            const auto b = static_cast<std::uint32_t>(random.below(boxes));
            pairs.push_back({a, b});
        }
    }
    return pairs;
}

}  // namespace obbsat::test_support
