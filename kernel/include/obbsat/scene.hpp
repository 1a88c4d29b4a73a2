// Seeded scenes shaped like a broadphase's output, for the demo, the tests and
// the benchmarks: rectangles with half extents in [0.5, 5] at random
// orientations, and candidate pairs whose centers lie closer than a radius.
// The radius sets how many candidates really collide.
//
// Generation uses only IEEE basic arithmetic (orientations come from the
// rational parametrisation of the unit circle, not from sin and cos), so the
// same seed gives the same bytes on every machine and standard library.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat {

/// How many candidate pairs collide, roughly: 5%, 30% or 80%.
enum class scene_density { sparse, typical, dense };

struct scene_spec {
    std::uint64_t seed = 1;
    std::size_t rects = 100000;       ///< rectangles in the scene
    std::size_t pairs = 1000000;      ///< candidate pairs wanted (fewer only if the scene has fewer)
    float candidate_radius = 12.0f;    ///< centers closer than this make a candidate pair
};

struct scene {
    rect_soa rects;
    std::vector<pair_index> pairs;  ///< a < b, sorted by a then b, as a broadphase emits them
};

/// The candidate radius that gives `density`'s share of colliding candidates.
float candidate_radius_for(scene_density density);

/// A spec for `density` with the given sizes and seed.
scene_spec scene_spec_for(scene_density density, std::size_t rects, std::size_t pairs,
                          std::uint64_t seed = 1);

/// Builds the scene of `spec`: deterministic for a given spec.
scene make_scene(const scene_spec& spec);

/// A small, fast, seedable generator (splitmix64), the same on every platform.
class seeded_random {
public:
    explicit seeded_random(std::uint64_t seed) : state_(seed) {}
    /// The next 64 random bits.
    std::uint64_t next();
    /// A float uniform in [lo, hi), from 24 random bits.
    float uniform(float lo, float hi);
    /// An integer uniform in [0, bound), bound > 0.
    std::uint64_t below(std::uint64_t bound);

private:
    std::uint64_t state_;
};

}  // namespace obbsat
