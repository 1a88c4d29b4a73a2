// Random pair batches for the equivalence tests, in three kinds:
// rectangles from random poses placed near each other, quadrilaterals that are
// not rectangles (random corners), and rectangles placed so they mostly
// overlap. The mix keeps both verdicts frequent. Poses go through
// rect_soa::from_poses (sin and cos), so these batches are not meant to be
// identical across machines; the golden digest does not use them.
#pragma once

#include <obbsat/pose.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>
#include <obbsat/scene.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace obbsat::test_support {

/// Rectangles a[i] and b[i] form pair i.
struct stream_batch {
    rect_soa a;
    rect_soa b;
};

namespace random_pairs_detail {

inline float random_size(seeded_random& random) {
    const int exponent = static_cast<int>(random.below(10)) - 4;
    return std::ldexp(random.uniform(1.0f, 2.0f), exponent);
}

inline pose random_pose(seeded_random& random, point center, float size) {
    const float hx = size * random.uniform(0.05f, 1.0f);
    const float hy = size * random.uniform(0.05f, 1.0f);
    const float angle = random.uniform(-3.14159265f, 3.14159265f);
    return pose{center, {hx, hy}, angle};
}

inline float reach(const pose& p) { return p.half_extents.x + p.half_extents.y; }

}  // namespace random_pairs_detail

/// `count` random pairs: 40% poses near each other, 30% non-rectangular
/// quadrilaterals, 30% rectangles placed to overlap mostly.
inline stream_batch random_stream_batch(seeded_random& random, std::size_t count) {
    using namespace random_pairs_detail;
    const std::size_t pose_pairs = count * 4 / 10;
    const std::size_t quad_pairs = count * 3 / 10;
    const std::size_t overlapping_pairs = count - pose_pairs - quad_pairs;

    std::vector<pose> poses_a, poses_b;
    poses_a.reserve(pose_pairs + overlapping_pairs);
    poses_b.reserve(pose_pairs + overlapping_pairs);
    for (std::size_t i = 0; i < pose_pairs + overlapping_pairs; ++i) {
        const bool overlapping = i >= pose_pairs;
        const point center_a{random.uniform(-1000.0f, 1000.0f), random.uniform(-1000.0f, 1000.0f)};
        const float size_a = random_size(random);
        const float size_b = overlapping ? size_a : random_size(random);
        const pose a = random_pose(random, center_a, size_a);
        // Near: offsets up to the sum of half extents on each axis; overlapping:
        // up to a quarter of the smaller half extent of A.
        const float spread =
            overlapping ? 0.25f * std::fmin(a.half_extents.x, a.half_extents.y) : reach(a) + size_b;
        const point center_b{center_a.x + spread * random.uniform(-1.0f, 1.0f),
                             center_a.y + spread * random.uniform(-1.0f, 1.0f)};
        poses_a.push_back(a);
        poses_b.push_back(random_pose(random, center_b, size_b));
    }
    stream_batch out{rect_soa::from_poses(poses_a), rect_soa::from_poses(poses_b)};
    out.a.reserve(count);
    out.b.reserve(count);
    for (std::size_t i = 0; i < quad_pairs; ++i) {
        const float size = random_size(random);
        const point center_a{random.uniform(-1000.0f, 1000.0f), random.uniform(-1000.0f, 1000.0f)};
        const point center_b{center_a.x + size * random.uniform(-2.0f, 2.0f),
                             center_a.y + size * random.uniform(-2.0f, 2.0f)};
        auto corner = [&](point c) {
            return point{c.x + size * random.uniform(-1.0f, 1.0f),
                         c.y + size * random.uniform(-1.0f, 1.0f)};
        };
        out.a.push_back(
            rect{corner(center_a), corner(center_a), corner(center_a), corner(center_a)});
        out.b.push_back(
            rect{corner(center_b), corner(center_b), corner(center_b), corner(center_b)});
    }
    return out;
}

}  // namespace obbsat::test_support
