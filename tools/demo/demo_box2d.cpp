#include "demo/demo_box2d.hpp"

#include <obbsat/pose.hpp>

#include <algorithm>
#include <chrono>

#if OBBSAT_DEMO_WITH_BOX2D
#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>
#endif

namespace obbsat::cli {

#if OBBSAT_DEMO_WITH_BOX2D

std::optional<peer_timing> time_box2d(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                      unsigned reps, const std::vector<std::uint8_t>& expected) {
    // Boxes in world coordinates, so every transform is the identity. Box2D
    // keeps a 0.01 skin around each polygon: near-touching pairs collide there.
    std::vector<b2PolygonShape> boxes(rects.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const pose p = pose_of(rects[i]);
        boxes[i].SetAsBox(p.half_extents.x, p.half_extents.y, b2Vec2(p.center.x, p.center.y), p.angle);
    }
    b2Transform identity;
    identity.SetIdentity();
    std::vector<std::uint8_t> verdicts(pairs.size());
    std::vector<double> times;
    for (unsigned rep = 0; rep <= reps; ++rep) {
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            b2Manifold manifold;
            b2CollidePolygons(&manifold, &boxes[pairs[i].a], identity, &boxes[pairs[i].b], identity);
            verdicts[i] = manifold.pointCount > 0 ? 1 : 0;
        }
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (rep > 0) {
            times.push_back(elapsed);
        }
    }
    std::sort(times.begin(), times.end());
    std::size_t same = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        same += verdicts[i] == expected[i] ? 1u : 0u;
    }
    return peer_timing{times[times.size() / 2],
                       pairs.empty() ? 1.0 : static_cast<double>(same) / static_cast<double>(pairs.size())};
}

#else

std::optional<peer_timing> time_box2d(const rect_soa&, const std::vector<pair_index>&, unsigned,
                                      const std::vector<std::uint8_t>&) {
    return std::nullopt;
}

#endif

}  // namespace obbsat::cli
