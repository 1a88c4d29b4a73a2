// Boost.Geometry's R-tree as a scene peer: what a developer of spatial tools
// would build. Each query: the obbsat bounds of every box (obbsat::ref::bounds_of,
// so the candidates are exactly the pairs find_pairs considers) as boxes of
// float; an rtree<., rstar<16>> built by its packing constructor (bulk
// loading; the split algorithm only matters for later inserts); one
// intersects() query per box, keeping the hits j > i; then obbsat's exact
// narrowphase on those candidates (scene_narrowphase.hpp). Boost's box
// intersects() is closed, as the bounds' overlap is.
//
// A frame rebuilds the tree: every box moved, and bulk loading N boxes beats
// N removals and insertions by far.
#include "bench_registry.hpp"
#include "scene_harness.hpp"
#include "scene_narrowphase.hpp"
#include "scene_parts.hpp"
#include "scene_workload.hpp"

#include <obbsat/pose_records.hpp>
#include <obbsat/ref/bounds.hpp>

#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace obbsat_bench {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using bg_point = bg::model::point<float, 2, bg::cs::cartesian>;
using bg_box = bg::model::box<bg_point>;
using tree_value = std::pair<bg_box, std::uint32_t>;
using rtree = bgi::rtree<tree_value, bgi::rstar<16>>;

class rtree_query final : public scene_query {
public:
    rtree_query(scene_workload& scene, unsigned threads) : scene_(&scene), parts_(threads) {}

    const std::vector<obbsat::pair_index>& find(scene_frame f) override {
        const obbsat::pose_records& poses = scene_->poses(f);
        values_.resize(poses.size());
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(poses[i]);
            values_[i] = {bg_box(bg_point(b.lo_x, b.lo_y), bg_point(b.hi_x, b.hi_y)),
                          static_cast<std::uint32_t>(i)};
        }
        tree_ = rtree(values_.begin(), values_.end());
        const auto parts = static_cast<unsigned>(parts_.size());
        run_parts(parts, [this, &poses, parts](unsigned part) {
            const part_range boxes = part_of(values_.size(), parts, part);
            part_pairs& mine = parts_[part];
            mine.candidates.clear();
            for (std::size_t i = boxes.begin; i < boxes.end; ++i) {
                const auto first = static_cast<std::uint32_t>(i);
                tree_.query(bgi::intersects(values_[i].first),
                            boost::make_function_output_iterator([&mine, first](const tree_value& hit) {
                                if (hit.second > first) {
                                    mine.candidates.push_back({first, hit.second});
                                }
                            }));
            }
            decide_exact(poses, mine);
        });
        candidates_ = join_parts(parts_, pairs_);
        return pairs_;
    }

    std::size_t candidates() const override { return candidates_; }

private:
    scene_workload* scene_;
    std::vector<part_pairs> parts_;
    std::vector<tree_value> values_;
    rtree tree_;
    std::size_t candidates_ = 0;
    std::vector<obbsat::pair_index> pairs_;
};

}  // namespace

void register_rtree_scene_peer() {
    scene_rows rows;
    rows.cold_prefix = "peer_scene/rtree";
    rows.frame_prefix = "peer_frame/rtree";
    rows.thread_counts = {1, 2};
    rows.expected = {obbsat::store_kind::poses, obbsat::method::exact, true};
    rows.prepare = [](scene_workload& w, scene_row_kind) -> scene_query_factory {
        return [&w](unsigned threads) -> std::unique_ptr<scene_query> {
            return std::make_unique<rtree_query>(w, threads);
        };
    };
    register_scene_rows(rows);
}

}  // namespace obbsat_bench
