// contacts/poses/indexed/<backend>/pairs:<N>/threads:1: contact_pairs over
// pose_records on the collide rows' pairs (their generator's order), beside
// contacts/local_verdicts/poses/indexed/<backend>/...: the verdict-only local
// method on the same pairs in the same binary, and
// distances/poses/indexed/<backend>/...: distance_pairs on them, and
// contacts64/poses/indexed/<backend>/...: contact_pairs over pose_records64
// holding the same poses, every float taken exactly, on the double lanes (the
// double reference for scalar). Each row checks its answers against the
// reference before it times anything.
#include "bench_registry.hpp"
#include "contact_workload.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/distance.hpp>
#include <obbsat/ref/local.hpp>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace obbsat_bench {

workload& contact_workload(std::size_t pairs) {
    static std::map<std::size_t, std::unique_ptr<workload>> cache;
    std::unique_ptr<workload>& w = cache[pairs];
    if (!w) {
        w = std::make_unique<workload>(pairs, obbsat::scene_density::typical);
    }
    return *w;
}

namespace {

/// The workload's poses as double records: the same rectangles, every float
/// taken exactly, built once per size.
const obbsat::pose_records64& double_poses(std::size_t count) {
    static std::map<std::size_t, std::unique_ptr<obbsat::pose_records64>> cache;
    std::unique_ptr<obbsat::pose_records64>& records = cache[count];
    if (!records) {
        const obbsat::pose_records& poses = contact_workload(count).poses();
        std::vector<obbsat::rect_pose64> rows(poses.size());
        for (std::size_t i = 0; i < poses.size(); ++i) {
            const obbsat::rect_pose p = poses[i];
            rows[i] = {{p.center.x, p.center.y}, {p.half_extents.x, p.half_extents.y}, {p.rotation.x, p.rotation.y}};
        }
        records = std::make_unique<obbsat::pose_records64>(rows);
    }
    return *records;
}

/// contact_pairs over `poses` (float or double records) on the workload's
/// pairs, after checking every contact byte for byte against the reference.
template <class Records, class Contact, class Options>
void time_contacts_of(benchmark::State& state, const Records& poses, obbsat::backend use, std::size_t count) {
    const std::vector<obbsat::pair_index>& pairs = contact_workload(count).sorted_pairs();
    Options options;
    options.use = use;
    std::vector<Contact> out(count);
    obbsat::contact_pairs(poses, pairs.data(), count, out.data(), options);
    std::size_t colliding = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const Contact expected = obbsat::ref::contact_of(poses[pairs[i].a], poses[pairs[i].b]);
        if (std::memcmp(&expected, &out[i], sizeof expected) != 0) {
            state.SkipWithError(("pair " + std::to_string(i) + " differs from the reference").c_str());
            return;
        }
        colliding += out[i].point_count > 0 ? 1u : 0u;
    }
    for (auto _ : state) {
        obbsat::contact_pairs(poses, pairs.data(), count, out.data(), options);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    set_pair_rate_counters(state, count);
    state.counters["with_points"] = static_cast<double>(colliding) / static_cast<double>(count);
}

void time_contacts(benchmark::State& state, obbsat::backend use, std::size_t count) {
    time_contacts_of<obbsat::pose_records, obbsat::contact, obbsat::contact_options>(state, contact_workload(count).poses(), use, count);
}

void time_contacts64(benchmark::State& state, obbsat::backend use, std::size_t count) {
    time_contacts_of<obbsat::pose_records64, obbsat::contact64, obbsat::contact_options64>(state, double_poses(count),
                                                                                          use, count);
}

void time_distances(benchmark::State& state, obbsat::backend use, std::size_t count) {
    workload& w = contact_workload(count);
    const obbsat::pose_records& poses = w.poses();
    const std::vector<obbsat::pair_index>& pairs = w.sorted_pairs();
    obbsat::distance_options options;
    options.use = use;
    std::vector<obbsat::closest_points> out(count);
    obbsat::distance_pairs(poses, pairs.data(), count, out.data(), options);
    for (std::size_t i = 0; i < count; ++i) {
        const obbsat::closest_points expected = obbsat::ref::distance_of(poses[pairs[i].a], poses[pairs[i].b]);
        if (std::memcmp(&expected, &out[i], sizeof expected) != 0) {
            state.SkipWithError(("pair " + std::to_string(i) + " differs from the reference").c_str());
            return;
        }
    }
    for (auto _ : state) {
        obbsat::distance_pairs(poses, pairs.data(), count, out.data(), options);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    set_pair_rate_counters(state, count);
}

void time_local_verdicts(benchmark::State& state, obbsat::backend use, std::size_t count) {
    workload& w = contact_workload(count);
    const obbsat::pose_records& poses = w.poses();
    const std::vector<obbsat::pair_index>& pairs = w.sorted_pairs();
    obbsat::collide_options options;
    options.test = obbsat::method::local;
    options.use = use;
    std::vector<std::uint8_t> verdicts(count);
    obbsat::collide_pairs(poses, pairs.data(), count, verdicts.data(), options);
    for (std::size_t i = 0; i < count; ++i) {
        if ((verdicts[i] != 0) != obbsat::ref::local(poses[pairs[i].a], poses[pairs[i].b])) {
            state.SkipWithError(("pair " + std::to_string(i) + " differs from the reference").c_str());
            return;
        }
    }
    for (auto _ : state) {
        obbsat::collide_pairs(poses, pairs.data(), count, verdicts.data(), options);
        benchmark::DoNotOptimize(verdicts.data());
        benchmark::ClobberMemory();
    }
    set_pair_rate_counters(state, count);
}

}  // namespace

void register_contact_benchmarks() {
    for (const obbsat::backend use : obbsat::compiled_backends()) {
        if (!obbsat::cpu_supports(use)) {
            continue;
        }
        const std::string backend = obbsat::backend_name(use);
        for (const std::size_t count : contact_sizes) {
            const std::string tail = backend + "/pairs:" + std::to_string(count) + "/threads:1";
            benchmark::RegisterBenchmark(("contacts/poses/indexed/" + tail).c_str(),
                                         [use, count](benchmark::State& s) { time_contacts(s, use, count); })
                ->UseRealTime();
            benchmark::RegisterBenchmark(("contacts64/poses/indexed/" + tail).c_str(),
                                         [use, count](benchmark::State& s) { time_contacts64(s, use, count); })
                ->UseRealTime();
            benchmark::RegisterBenchmark(("distances/poses/indexed/" + tail).c_str(),
                                         [use, count](benchmark::State& s) { time_distances(s, use, count); })
                ->UseRealTime();
            benchmark::RegisterBenchmark(("contacts/local_verdicts/poses/indexed/" + tail).c_str(),
                                         [use, count](benchmark::State& s) { time_local_verdicts(s, use, count); })
                ->UseRealTime();
        }
    }
}

}  // namespace obbsat_bench
