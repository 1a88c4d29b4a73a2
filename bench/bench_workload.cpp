#include "bench_workload.hpp"

#include <obbsat/oracle/contact.hpp>
#include <obbsat/ref/conservative.hpp>
#include <obbsat/ref/sat4.hpp>
#include <obbsat/ref/sat4_centered.hpp>
#include <obbsat/ref/sat4_double.hpp>

#include <stdexcept>
#include <utility>

namespace obbsat_bench {

namespace {

// The generator's seed for every scene, and the shuffle's: fixed so that runs
// on different days and machines time the same bytes.
constexpr std::uint64_t scene_seed = 1;
constexpr std::uint64_t shuffle_seed = 2;

bool reference_collides(obbsat::method test, const obbsat::rect& a, const obbsat::rect& b) {
    return obbsat::method_reference(test)(a, b);
}

std::vector<obbsat::pair_index> seeded_shuffle(std::vector<obbsat::pair_index> pairs,
                                               std::uint64_t seed) {
    // Our own Fisher-Yates on the library's splitmix64: std::shuffle's
    // algorithm differs between standard libraries, this does not.
    obbsat::seeded_random random(seed);
    for (std::size_t i = pairs.size(); i > 1; --i) {
        const auto j = static_cast<std::size_t>(random.below(i));
        std::swap(pairs[i - 1], pairs[j]);
    }
    return pairs;
}

}  // namespace

const char* density_name(obbsat::scene_density density) {
    switch (density) {
        case obbsat::scene_density::sparse: return "sparse";
        case obbsat::scene_density::typical: return "typical";
        case obbsat::scene_density::dense: return "dense";
    }
    return "unknown";
}

std::vector<std::uint8_t> reference_verdicts(obbsat::method test, const obbsat::rect_soa& rects,
                                             const std::vector<obbsat::pair_index>& pairs) {
    std::vector<std::uint8_t> verdicts(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        verdicts[i] = reference_collides(test, rects[pairs[i].a], rects[pairs[i].b]) ? 1 : 0;
    }
    return verdicts;
}

workload::workload(std::size_t pairs, obbsat::scene_density density)
    : scene_(obbsat::make_scene(obbsat::scene_spec_for(density, pairs / 2, pairs, scene_seed))) {
    if (scene_.pairs.size() != pairs) {
        throw std::runtime_error(std::string("the ") + density_name(density) + " scene of " +
                                 std::to_string(pairs / 2) + " rectangles has " +
                                 std::to_string(scene_.pairs.size()) + " candidate pairs, not " +
                                 std::to_string(pairs));
    }
    records_.reserve(scene_.rects.size());
    for (std::size_t i = 0; i < scene_.rects.size(); ++i) {
        records_.push_back(scene_.rects[i]);
    }
    shuffled_pairs_ = seeded_shuffle(scene_.pairs, shuffle_seed);
}

const std::vector<std::uint8_t>& workload::sorted_reference(obbsat::method test) {
    auto found = sorted_reference_.find(test);
    if (found == sorted_reference_.end()) {
        found = sorted_reference_.emplace(test, reference_verdicts(test, rects(), sorted_pairs())).first;
    }
    return found->second;
}

const std::vector<std::uint8_t>& workload::shuffled_reference(obbsat::method test) {
    auto found = shuffled_reference_.find(test);
    if (found == shuffled_reference_.end()) {
        found = shuffled_reference_.emplace(test, reference_verdicts(test, rects(), shuffled_pairs()))
                    .first;
    }
    return found->second;
}

const obbsat::rect_soa& workload::stream_a() {
    build_streams();
    return *stream_a_;
}

const obbsat::rect_soa& workload::stream_b() {
    build_streams();
    return *stream_b_;
}

void workload::build_streams() {
    if (stream_a_) {
        return;
    }
    auto a = std::make_unique<obbsat::rect_soa>();
    auto b = std::make_unique<obbsat::rect_soa>();
    a->reserve(scene_.pairs.size());
    b->reserve(scene_.pairs.size());
    for (const obbsat::pair_index& p : scene_.pairs) {
        a->push_back(scene_.rects[p.a]);
        b->push_back(scene_.rects[p.b]);
    }
    stream_a_ = std::move(a);
    stream_b_ = std::move(b);
}

const obbsat::pose_records& workload::poses() {
    if (!poses_) {
        poses_ = std::make_unique<obbsat::pose_records>(obbsat::pose_records::from_corners(records_));
    }
    return *poses_;
}

const std::vector<obbsat::rect_pose>& workload::pose_rows() {
    if (pose_rows_.empty()) {
        const obbsat::pose_records& store = poses();
        pose_rows_.reserve(store.size());
        for (std::size_t i = 0; i < store.size(); ++i) {
            pose_rows_.push_back(store[i]);
        }
    }
    return pose_rows_;
}

namespace {

std::vector<std::uint8_t> pose_reference_verdicts(obbsat::method test, const obbsat::pose_records& poses,
                                                  const std::vector<obbsat::pair_index>& pairs) {
    const obbsat::pose_reference_fn reference = obbsat::pose_method_reference(test);
    std::vector<std::uint8_t> verdicts(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        verdicts[i] = reference(poses[pairs[i].a], poses[pairs[i].b]) ? 1 : 0;
    }
    return verdicts;
}

}  // namespace

const std::vector<std::uint8_t>& workload::pose_sorted_reference(obbsat::method test) {
    auto found = pose_sorted_reference_.find(test);
    if (found == pose_sorted_reference_.end()) {
        found = pose_sorted_reference_.emplace(test, pose_reference_verdicts(test, poses(), sorted_pairs())).first;
    }
    return found->second;
}

const std::vector<std::uint8_t>& workload::pose_shuffled_reference(obbsat::method test) {
    auto found = pose_shuffled_reference_.find(test);
    if (found == pose_shuffled_reference_.end()) {
        found =
            pose_shuffled_reference_.emplace(test, pose_reference_verdicts(test, poses(), shuffled_pairs())).first;
    }
    return found->second;
}

const obbsat::pose_records& workload::pose_stream_a() {
    build_pose_streams();
    return *pose_stream_a_;
}

const obbsat::pose_records& workload::pose_stream_b() {
    build_pose_streams();
    return *pose_stream_b_;
}

const obbsat::pose_soa& workload::pose_soa_stream_a() {
    if (!pose_soa_stream_a_) {
        pose_soa_stream_a_ = std::make_unique<obbsat::pose_soa>(pose_stream_a());
    }
    return *pose_soa_stream_a_;
}

const obbsat::pose_soa& workload::pose_soa_stream_b() {
    if (!pose_soa_stream_b_) {
        pose_soa_stream_b_ = std::make_unique<obbsat::pose_soa>(pose_stream_b());
    }
    return *pose_soa_stream_b_;
}

void workload::build_pose_streams() {
    if (pose_stream_a_) {
        return;
    }
    const obbsat::pose_records& all = poses();
    auto a = std::make_unique<obbsat::pose_records>();
    auto b = std::make_unique<obbsat::pose_records>();
    a->reserve(scene_.pairs.size());
    b->reserve(scene_.pairs.size());
    for (const obbsat::pair_index& p : scene_.pairs) {
        a->push_back(all[p.a]);
        b->push_back(all[p.b]);
    }
    pose_stream_a_ = std::move(a);
    pose_stream_b_ = std::move(b);
}

workload& workload_for(std::size_t pairs, obbsat::scene_density density) {
    static std::map<std::pair<std::size_t, obbsat::scene_density>, std::unique_ptr<workload>> cache;
    std::unique_ptr<workload>& slot = cache[{pairs, density}];
    if (!slot) {
        slot = std::make_unique<workload>(pairs, density);
    }
    return *slot;
}

}  // namespace obbsat_bench
