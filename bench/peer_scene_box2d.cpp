// Box2D 2.4 as a scene peer: the broadphase and narrowphase of a physics
// engine, as b2World drives them, without the solver. Each box is a body: a
// local b2PolygonShape (SetAsBox of its half extents) and a b2Transform from
// its pose, both built before timing as an engine holds them.
//
// Cold (the first find of a query): b2BroadPhase::CreateProxy for every box
// with its shape's AABB, UpdatePairs collecting the candidate pairs, then
// b2CollidePolygons on each, colliding when the manifold has points.
// Frame (later finds): as b2World::Step does it. MoveProxy for every box with
// its new AABB and displacement; the dynamic tree reinserts only the boxes
// that left their fattened AABB (b2_aabbExtension, 0.1), so UpdatePairs
// reports only pairs new to the contact list; the contact list keeps every
// pair whose fattened AABBs overlap (b2ContactManager::Collide drops the
// others) and the narrowphase runs on all of them.
//
// Rows stop at box2d_max_boxes: b2DynamicTree's incremental insertion, in the
// scene's random order, builds a tree whose queries slow down as it grows.
// Measured on the uniform scenes (one core, outside this program):
// UpdatePairs after creating every proxy took 2.1, 7.1 and 37 µs per box at
// 10^4, 10^5 and 10^6 boxes (tree quality, GetTreeQuality, 637, 1897, 7678);
// inserting in Morton order instead, 0.8, 1.1 and 1.9 µs. A cold 4M-box row
// would take minutes per iteration, and every frame row starts with one.
// The scene's order is kept, as every other row gets it.
//
// Box2D is single-threaded: threads:1 rows only. Its polygons carry a skin of
// b2_polygonRadius (0.01) on each side, so b2CollidePolygons reports pairs up
// to 0.02 apart: its pairs are compared with the exact ones (agreement
// counters) but never required to match.
#include "bench_registry.hpp"
#include "scene_harness.hpp"
#include "scene_workload.hpp"

#include <obbsat/pose_records.hpp>

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <ostream>
#include <vector>

namespace obbsat_bench {

namespace {

/// The largest scene Box2D's rows are registered for (see above).
constexpr std::size_t box2d_max_boxes = 100000;

/// The bodies of one scene: a shape each and its transform in both frames.
struct box2d_bodies {
    const scene_workload* scene = nullptr;
    std::vector<b2PolygonShape> shapes;
    std::vector<b2Transform> transforms[2];

    const std::vector<b2Transform>& at(scene_frame f) const {
        return transforms[f == scene_frame::as_generated ? 0 : 1];
    }
};

b2Transform transform_of(const obbsat::rect_pose& p) {
    b2Transform xf;
    xf.p.Set(p.center.x, p.center.y);
    xf.q.s = p.rotation.y;
    xf.q.c = p.rotation.x;
    return xf;
}

/// The bodies of `w`, built on first request; only the latest scene's are
/// kept (a 4M-box scene's shapes take some 600 MB).
std::shared_ptr<const box2d_bodies> bodies_for(scene_workload& w) {
    static std::shared_ptr<box2d_bodies> latest;
    if (!latest || latest->scene != &w) {
        latest.reset();
        auto bodies = std::make_shared<box2d_bodies>();
        bodies->scene = &w;
        const obbsat::pose_records& start = w.poses(scene_frame::as_generated);
        const obbsat::pose_records& moved = w.poses(scene_frame::moved);
        bodies->shapes.resize(start.size());
        bodies->transforms[0].resize(start.size());
        bodies->transforms[1].resize(start.size());
        for (std::size_t i = 0; i < start.size(); ++i) {
            const obbsat::rect_pose p = start[i];
            bodies->shapes[i].SetAsBox(p.half_extents.x, p.half_extents.y);
            bodies->transforms[0][i] = transform_of(p);
            bodies->transforms[1][i] = transform_of(moved[i]);
        }
        latest = std::move(bodies);
    }
    return latest;
}

void* user_data_of(std::uint32_t box) {
    return reinterpret_cast<void*>(static_cast<std::uintptr_t>(box));
}

std::uint32_t box_of(void* user_data) {
    return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(user_data));
}

bool pair_less(const obbsat::pair_index& x, const obbsat::pair_index& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
}

bool pair_equal(const obbsat::pair_index& x, const obbsat::pair_index& y) {
    return x.a == y.a && x.b == y.b;
}

class box2d_query final : public scene_query {
public:
    explicit box2d_query(std::shared_ptr<const box2d_bodies> bodies) : bodies_(std::move(bodies)) {}

    const std::vector<obbsat::pair_index>& find(scene_frame f) override {
        const std::vector<b2PolygonShape>& shapes = bodies_->shapes;
        const std::vector<b2Transform>& xf = bodies_->at(f);
        const std::size_t n = shapes.size();
        if (proxies_.empty() && n != 0) {
            proxies_.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                b2AABB aabb;
                shapes[i].ComputeAABB(&aabb, xf[i], 0);
                proxies_[i] = broad_phase_.CreateProxy(aabb, user_data_of(static_cast<std::uint32_t>(i)));
            }
        } else {
            const std::vector<b2Transform>& before = bodies_->at(last_);
            for (std::size_t i = 0; i < n; ++i) {
                b2AABB aabb;
                shapes[i].ComputeAABB(&aabb, xf[i], 0);
                broad_phase_.MoveProxy(proxies_[i], aabb, xf[i].p - before[i].p);
            }
        }
        last_ = f;

        new_pairs_.clear();
        broad_phase_.UpdatePairs(this);
        // The contact manager keeps a pair once: b2ContactManager::AddPair
        // looks for it among the body's contacts; here a merge does that.
        if (contacts_.empty()) {
            contacts_.swap(new_pairs_);
        } else if (!new_pairs_.empty()) {
            contacts_.insert(contacts_.end(), new_pairs_.begin(), new_pairs_.end());
            std::sort(contacts_.begin(), contacts_.end(), pair_less);
            contacts_.erase(std::unique(contacts_.begin(), contacts_.end(), pair_equal), contacts_.end());
        }

        // b2ContactManager::Collide: a contact whose fattened AABBs no longer
        // overlap is destroyed, every other one goes through the narrowphase.
        pairs_.clear();
        std::size_t kept = 0;
        for (const obbsat::pair_index c : contacts_) {
            if (!broad_phase_.TestOverlap(proxies_[c.a], proxies_[c.b])) {
                continue;
            }
            contacts_[kept++] = c;
            b2Manifold manifold;
            b2CollidePolygons(&manifold, &shapes[c.a], xf[c.a], &shapes[c.b], xf[c.b]);
            if (manifold.pointCount > 0) {
                pairs_.push_back(c);
            }
        }
        contacts_.resize(kept);
        return pairs_;
    }

    std::size_t candidates() const override { return contacts_.size(); }

    /// b2BroadPhase::UpdatePairs' callback: one pair each, never twice.
    void AddPair(void* user_a, void* user_b) {
        const std::uint32_t a = box_of(user_a);
        const std::uint32_t b = box_of(user_b);
        new_pairs_.push_back({std::min(a, b), std::max(a, b)});
    }

private:
    std::shared_ptr<const box2d_bodies> bodies_;
    b2BroadPhase broad_phase_;
    std::vector<std::int32_t> proxies_;
    scene_frame last_ = scene_frame::as_generated;
    std::vector<obbsat::pair_index> new_pairs_;
    std::vector<obbsat::pair_index> contacts_;
    std::vector<obbsat::pair_index> pairs_;
};

}  // namespace

void register_box2d_scene_peer(std::ostream& skipped) {
    scene_rows rows;
    rows.cold_prefix = "peer_scene/box2d";
    rows.frame_prefix = "peer_frame/box2d";
    rows.thread_counts = {1};
    rows.expected = {obbsat::store_kind::poses, obbsat::method::exact, false};
    rows.prepare = [](scene_workload& w, scene_row_kind) -> scene_query_factory {
        std::shared_ptr<const box2d_bodies> bodies = bodies_for(w);
        return [bodies](unsigned) -> std::unique_ptr<scene_query> { return std::make_unique<box2d_query>(bodies); };
    };
    rows.max_boxes = box2d_max_boxes;
    for (const std::size_t boxes : register_scene_rows(rows)) {
        skipped << "obbsat_bench: skipping peer_scene/box2d/boxes:" << boxes << "/*, peer_frame/box2d/boxes:"
                << boxes << "/*: b2DynamicTree built in random order is too slow above " << box2d_max_boxes
                << " boxes\n";
    }
}

}  // namespace obbsat_bench
