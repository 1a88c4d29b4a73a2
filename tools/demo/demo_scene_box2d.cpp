#include "demo/demo_scene_box2d.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>

#if OBBSAT_DEMO_WITH_BOX2D
#include <box2d/b2_broad_phase.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>
#endif

namespace obbsat::cli {

#if OBBSAT_DEMO_WITH_BOX2D

namespace {

/// Collects b2BroadPhase::UpdatePairs' candidate pairs, smaller index first.
struct pair_collector {
    std::vector<pair_index> pairs;
    void AddPair(void* user_a, void* user_b) {
        auto a = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(user_a));
        auto b = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(user_b));
        pairs.push_back(a < b ? pair_index{a, b} : pair_index{b, a});
    }
};

bool pair_less(const pair_index& x, const pair_index& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; }

}  // namespace

std::optional<scene_peer_timing> time_box2d_scene(const std::vector<rect_pose>& poses,
                                                  const std::vector<pair_index>& exact) {
    // Bodies as an engine holds them, built before the clock starts: a local
    // box shape and a transform from the pose.
    const std::size_t n = poses.size();
    std::vector<b2PolygonShape> shapes(n);
    std::vector<b2Transform> transforms(n);
    for (std::size_t i = 0; i < n; ++i) {
        shapes[i].SetAsBox(poses[i].half_extents.x, poses[i].half_extents.y);
        transforms[i].p.Set(poses[i].center.x, poses[i].center.y);
        transforms[i].q.c = poses[i].rotation.x;
        transforms[i].q.s = poses[i].rotation.y;
    }
    const auto start = std::chrono::steady_clock::now();
    b2BroadPhase broad_phase;
    for (std::size_t i = 0; i < n; ++i) {
        b2AABB aabb;
        shapes[i].ComputeAABB(&aabb, transforms[i], 0);
        broad_phase.CreateProxy(aabb, reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    }
    pair_collector candidates;
    broad_phase.UpdatePairs(&candidates);
    std::vector<pair_index> found;
    for (const pair_index& c : candidates.pairs) {
        b2Manifold manifold;
        b2CollidePolygons(&manifold, &shapes[c.a], transforms[c.a], &shapes[c.b], transforms[c.b]);
        if (manifold.pointCount > 0) {
            found.push_back(c);
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::sort(found.begin(), found.end(), pair_less);
    std::vector<pair_index> extra, missed;
    std::set_difference(found.begin(), found.end(), exact.begin(), exact.end(), std::back_inserter(extra), pair_less);
    std::set_difference(exact.begin(), exact.end(), found.begin(), found.end(), std::back_inserter(missed), pair_less);
    return scene_peer_timing{seconds, found.size(), extra.size(), missed.size()};
}

#else

std::optional<scene_peer_timing> time_box2d_scene(const std::vector<rect_pose>&, const std::vector<pair_index>&) {
    return std::nullopt;
}

#endif

}  // namespace obbsat::cli
