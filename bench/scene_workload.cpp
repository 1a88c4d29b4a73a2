#include "scene_workload.hpp"

#include <obbsat/pose_conversion.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>

namespace obbsat_bench {

namespace {

// Fixed so that runs on different days and machines time the same bytes.
constexpr std::uint64_t scene_seed = 1;
constexpr std::uint64_t motion_seed = 3;

std::size_t frame_slot(scene_frame f) {
    return f == scene_frame::as_generated ? 0 : 1;
}

obbsat::pose_records moved_copy(const obbsat::pose_records& poses) {
    obbsat::seeded_random random(motion_seed);
    obbsat::pose_records out;
    out.reserve(poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        obbsat::rect_pose p = poses[i];
        const std::uint64_t signs = random.next();
        p.center.x += (signs & 1u) != 0 ? frame_step : -frame_step;
        p.center.y += (signs & 2u) != 0 ? frame_step : -frame_step;
        out.push_back(p);
    }
    return out;
}

/// Every pair (i, j), i < j, whose closed bounds overlap, in no particular
/// order: a sweep over x in order of lo_x, each box against the boxes whose
/// lo_x lies in its own x range. Quadratic in a dense column, but simple
/// enough to trust, and only run on the checked sizes.
std::vector<obbsat::pair_index> overlapping_bounds(const std::vector<obbsat::ref::box_bounds>& bounds) {
    std::vector<std::uint32_t> order(bounds.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&bounds](std::uint32_t a, std::uint32_t b) {
        return bounds[a].lo_x < bounds[b].lo_x;
    });
    std::vector<obbsat::pair_index> out;
    for (std::size_t p = 0; p < order.size(); ++p) {
        const obbsat::ref::box_bounds& a = bounds[order[p]];
        for (std::size_t q = p + 1; q < order.size() && bounds[order[q]].lo_x <= a.hi_x; ++q) {
            if (obbsat::ref::bounds_overlap(a, bounds[order[q]])) {
                out.push_back({std::min(order[p], order[q]), std::max(order[p], order[q])});
            }
        }
    }
    return out;
}

void sort_pairs(std::vector<obbsat::pair_index>& pairs) {
    std::sort(pairs.begin(), pairs.end(), [](const obbsat::pair_index& x, const obbsat::pair_index& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
}

std::size_t parse_box_count(const std::string& text) {
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || text[0] == '-' || value == 0 || value > 0xFFFFFFFFull) {
        throw std::runtime_error("OBBSAT_BENCH_SCENE_BOXES: '" + text +
                                 "' is not a box count (1 to 4294967295)");
    }
    return static_cast<std::size_t>(value);
}

}  // namespace

std::vector<std::size_t> scene_box_counts_to_register() {
    const char* chosen = std::getenv("OBBSAT_BENCH_SCENE_BOXES");
    if (chosen == nullptr || *chosen == '\0') {
        return {std::begin(scene_box_counts), std::end(scene_box_counts)};
    }
    std::vector<std::size_t> out;
    std::string list(chosen);
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        out.push_back(parse_box_count(list.substr(start, comma - start)));
        start = comma + 1;
    }
    return out;
}

std::string scene_name_tail(std::size_t boxes, obbsat::scene_sizes sizes, unsigned threads) {
    return "boxes:" + std::to_string(boxes) + "/sizes:" + obbsat::scene_sizes_name(sizes) +
           "/threads:" + std::to_string(threads);
}

scene_workload::scene_workload(std::size_t boxes, obbsat::scene_sizes sizes) {
    obbsat::pose_scene_spec spec;
    spec.seed = scene_seed;
    spec.boxes = boxes;
    spec.sizes = sizes;
    spec.pairs_per_box = scene_pairs_per_box;
    poses_[0] = std::make_unique<obbsat::pose_records>(obbsat::make_pose_scene(spec));
}

const obbsat::pose_records& scene_workload::poses(scene_frame f) {
    const std::size_t slot = frame_slot(f);
    if (!poses_[slot]) {
        poses_[slot] = std::make_unique<obbsat::pose_records>(moved_copy(*poses_[0]));
    }
    return *poses_[slot];
}

const obbsat::rect_records& scene_workload::corners(scene_frame f) {
    const std::size_t slot = frame_slot(f);
    if (!corners_[slot]) {
        corners_[slot] = std::make_unique<obbsat::rect_records>(obbsat::corner_records_of(poses(f)));
    }
    return *corners_[slot];
}

const std::vector<obbsat::pair_index>& scene_workload::candidate_pairs(scene_frame f,
                                                                       obbsat::store_kind store) {
    const frame_store key{f, store};
    auto found = candidates_.find(key);
    if (found == candidates_.end()) {
        std::vector<obbsat::ref::box_bounds> bounds(size());
        for (std::size_t i = 0; i < bounds.size(); ++i) {
            bounds[i] = store == obbsat::store_kind::poses ? obbsat::ref::bounds_of(poses(f)[i])
                                                           : obbsat::ref::bounds_of(corners(f)[i]);
        }
        found = candidates_.emplace(key, overlapping_bounds(bounds)).first;
    }
    return found->second;
}

const std::vector<obbsat::pair_index>& scene_workload::reference_pairs(scene_frame f, obbsat::store_kind store,
                                                                       obbsat::method test) {
    const auto key = std::make_pair(frame_store{f, store}, test);
    auto found = references_.find(key);
    if (found != references_.end()) {
        return found->second;
    }
    if (!obbsat::runs_on(test, store)) {
        throw std::runtime_error(std::string("method ") + obbsat::method_name(test) + " does not run on " +
                                 obbsat::store_name(store));
    }
    std::vector<obbsat::pair_index> colliding;
    for (const obbsat::pair_index& p : candidate_pairs(f, store)) {
        const bool collides = store == obbsat::store_kind::poses
                                  ? obbsat::pose_method_reference(test)(poses(f)[p.a], poses(f)[p.b])
                                  : obbsat::method_reference(test)(corners(f)[p.a], corners(f)[p.b]);
        if (collides) {
            colliding.push_back(p);
        }
    }
    sort_pairs(colliding);
    return references_.emplace(key, std::move(colliding)).first->second;
}

scene_workload& scene_workload_for(std::size_t boxes, obbsat::scene_sizes sizes) {
    static std::map<std::pair<std::size_t, obbsat::scene_sizes>, std::unique_ptr<scene_workload>> cache;
    std::unique_ptr<scene_workload>& slot = cache[{boxes, sizes}];
    if (!slot) {
        slot = std::make_unique<scene_workload>(boxes, sizes);
    }
    return *slot;
}

}  // namespace obbsat_bench
