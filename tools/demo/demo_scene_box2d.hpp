// The demo's scene peer: Box2D 2.4's broadphase (b2BroadPhase: a proxy per
// box, UpdatePairs) and narrowphase (b2CollidePolygons on every candidate),
// one thread, as an engine runs them, when libbox2d-dev was found at
// configure time.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>

#include <optional>
#include <vector>

namespace obbsat::cli {

struct scene_peer_timing {
    double seconds;      ///< one cold query: proxies created, pairs found and decided
    std::size_t pairs;   ///< pairs Box2D reports colliding
    std::size_t extra;   ///< of those, pairs the exact answer does not have (Box2D's skin)
    std::size_t missed;  ///< exact pairs Box2D does not report
};

/// Times one cold Box2D query over `poses` and compares its pairs with
/// `exact` (sorted), or nothing when this build has no Box2D.
std::optional<scene_peer_timing> time_box2d_scene(const std::vector<rect_pose>& poses,
                                                  const std::vector<pair_index>& exact);

}  // namespace obbsat::cli
