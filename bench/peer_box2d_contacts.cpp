// contacts/poses/indexed/box2d/pairs:<N>/threads:1: Box2D 2.4's
// b2CollidePolygons, the manifold a physics engine builds per pair, on the
// pairs of the contact rows (contact_workload.hpp), each pose made a
// b2PolygonShape of the same center, size and angle in world coordinates.
// Its with_points counter is the share of pairs given points, as obbsat's
// rows count it; obbsat_box2d_contact_compare (box2d_contact_compare.cpp)
// compares the manifolds themselves.
#include "bench_registry.hpp"
#include "contact_workload.hpp"

#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <cmath>
#include <string>
#include <vector>

namespace obbsat_bench {

namespace {

void time_box2d_contacts(benchmark::State& state, std::size_t count) {
    workload& w = contact_workload(count);
    const obbsat::pose_records& poses = w.poses();
    const std::vector<obbsat::pair_index>& pairs = w.sorted_pairs();
    std::vector<b2PolygonShape> boxes(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const obbsat::rect_pose p = poses[i];
        const float length = std::sqrt((p.rotation.x * p.rotation.x) + (p.rotation.y * p.rotation.y));
        boxes[i].SetAsBox(p.half_extents.x * length, p.half_extents.y * length, b2Vec2(p.center.x, p.center.y),
                          std::atan2(p.rotation.y, p.rotation.x));
    }
    b2Transform identity;
    identity.SetIdentity();
    std::vector<b2Manifold> manifolds(count);
    for (auto _ : state) {
        for (std::size_t i = 0; i < count; ++i) {
            b2CollidePolygons(&manifolds[i], &boxes[pairs[i].a], identity, &boxes[pairs[i].b], identity);
        }
        benchmark::DoNotOptimize(manifolds.data());
        benchmark::ClobberMemory();
    }
    set_pair_rate_counters(state, count);
    // Comparable with obbsat's rows' with_points: Box2D's is larger by the
    // pairs apart by at most its two skins (2 · b2_polygonRadius).
    std::size_t with_points = 0;
    for (const b2Manifold& m : manifolds) {
        with_points += m.pointCount > 0 ? 1u : 0u;
    }
    state.counters["with_points"] = static_cast<double>(with_points) / static_cast<double>(count);
}

}  // namespace

void register_box2d_contact_peer() {
    for (const std::size_t count : contact_sizes) {
        benchmark::RegisterBenchmark(
            ("contacts/poses/indexed/box2d/pairs:" + std::to_string(count) + "/threads:1").c_str(),
            [count](benchmark::State& s) { time_box2d_contacts(s, count); })
            ->UseRealTime();
    }
}

}  // namespace obbsat_bench
