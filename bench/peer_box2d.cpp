// Box2D 2.4 as a peer: the narrow phase a physics engine would run on the
// same candidate pairs. Two entry points: b2CollidePolygons (SAT that also
// builds a contact manifold) and b2TestOverlap (GJK distance).
//
// Box2D gives every polygon a skin of b2_polygonRadius (0.01 length units)
// and reports contact while the skins overlap, so pairs that are near-touching
// but separated count as colliding there and not in sat4. Agreement below 1 is
// therefore expected, and the disagreements should be peer_only.
#include "bench_registry.hpp"
#include "peer_harness.hpp"
#include "pose_from_corners.hpp"

#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <map>
#include <vector>

namespace obbsat_bench {

namespace {

// Boxes in world coordinates (center and angle baked into the vertices) so
// every body transform is the identity; both Box2D peers share them.
const std::vector<b2PolygonShape>& box2d_boxes(workload& w) {
    static std::map<const workload*, std::vector<b2PolygonShape>> cache;
    std::vector<b2PolygonShape>& boxes = cache[&w];
    if (boxes.empty()) {
        boxes.resize(w.rects().size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const obbsat::pose p = pose_from_corners(w.rects()[i]);
            boxes[i].SetAsBox(p.half_extents.x, p.half_extents.y,
                              b2Vec2(p.center.x, p.center.y), p.angle);
        }
    }
    return boxes;
}

b2Transform identity_transform() {
    b2Transform xf;
    xf.SetIdentity();
    return xf;
}

}  // namespace

void register_box2d_peers() {
    register_peer("box2d_collide_polygons", [](workload& w) {
        const std::vector<b2PolygonShape>* boxes = &box2d_boxes(w);
        const b2Transform xf = identity_transform();
        return [boxes, xf](std::uint32_t a, std::uint32_t b) {
            b2Manifold manifold;
            b2CollidePolygons(&manifold, &(*boxes)[a], xf, &(*boxes)[b], xf);
            return manifold.pointCount > 0;
        };
    });
    register_peer("box2d_test_overlap", [](workload& w) {
        const std::vector<b2PolygonShape>* boxes = &box2d_boxes(w);
        const b2Transform xf = identity_transform();
        return [boxes, xf](std::uint32_t a, std::uint32_t b) {
            return b2TestOverlap(&(*boxes)[a], 0, &(*boxes)[b], 0, xf, xf);
        };
    });
}

}  // namespace obbsat_bench
