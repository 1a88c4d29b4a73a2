// The demo's peer row: Box2D 2.4's narrow phase (b2CollidePolygons, one
// thread, as Box2D runs it) on the demo's own pairs, when libbox2d-dev was
// found at configure time.
#pragma once

#include <obbsat/rect.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace obbsat::cli {

struct peer_timing {
    double median_seconds;  ///< over all pairs, median of the timed runs
    double agreement;       ///< share of pairs where the peer's verdict equals `expected`
};

/// Times Box2D on the pairs (reps timed runs after one warm-up), or nothing
/// when this build has no Box2D.
std::optional<peer_timing> time_box2d(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                      unsigned reps, const std::vector<std::uint8_t>& expected);

}  // namespace obbsat::cli
