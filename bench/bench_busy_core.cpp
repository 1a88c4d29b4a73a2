// find_pairs on a machine with other work on it: the same rows with and
// without a thread that spins on one core for the whole row.
//
//   busy_core/local/poses/boxes:<N>/sizes:uniform/threads:<T>/spinner:<off|on>
//
// With the spinner on, one core is taken: a query on two threads has one of
// them on a shared core. Units taken as they come (kernel/support/
// work_shares.hpp) let the other thread do most of the work, so two threads
// should be no slower than one; quiet, two threads should come close to
// twice one. The spinner is pinned to the last CPU where the system allows
// it (pthread_setaffinity_np), starts before the row's first iteration and
// is stopped after its last. The pairs of every thread count are checked
// against those of one thread before anything is timed.
#include "bench_registry.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>

#include <benchmark/benchmark.h>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace obbsat_bench {

namespace {

/// A thread that keeps one core busy until it is destroyed.
class core_spinner {
public:
    core_spinner() {
        thread_ = std::thread([this] {
            unsigned long long turns = 0;
            while (!stop_.load(std::memory_order_relaxed)) {
                ++turns;
            }
            benchmark::DoNotOptimize(turns);
        });
        pinned_ = pin_to_last_cpu();
    }
    ~core_spinner() {
        stop_.store(true);
        thread_.join();
    }
    core_spinner(const core_spinner&) = delete;
    core_spinner& operator=(const core_spinner&) = delete;

    bool pinned() const { return pinned_; }

private:
    bool pin_to_last_cpu() {
#if defined(__linux__)
        const unsigned cpus = std::thread::hardware_concurrency();
        if (cpus < 2) {
            return false;
        }
        cpu_set_t set;
        CPU_ZERO(&set);
        CPU_SET(cpus - 1, &set);
        return pthread_setaffinity_np(thread_.native_handle(), sizeof set, &set) == 0;
#else
        return false;
#endif
    }

    std::atomic<bool> stop_{false};
    std::thread thread_;
    bool pinned_ = false;
};

/// The scene of every row, made once, and its pairs on one thread.
struct busy_scene {
    obbsat::pose_records poses;
    std::vector<obbsat::pair_index> pairs;
};

obbsat::collide_options options_for(unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::local;
    options.threads = threads;
    return options;
}

const busy_scene& scene_of(std::size_t boxes) {
    static std::unique_ptr<busy_scene> made;
    if (!made || made->poses.size() != boxes) {
        obbsat::pose_scene_spec spec;
        spec.boxes = boxes;
        spec.sizes = obbsat::scene_sizes::uniform;
        made = std::make_unique<busy_scene>();
        made->poses = obbsat::pose_records(obbsat::make_pose_scene(spec));
        made->pairs = obbsat::find_pairs(made->poses, options_for(1));
    }
    return *made;
}

bool same_pairs(const std::vector<obbsat::pair_index>& x, const std::vector<obbsat::pair_index>& y) {
    if (x.size() != y.size()) {
        return false;
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i].a != y[i].a || x[i].b != y[i].b) {
            return false;
        }
    }
    return true;
}

void busy_core_find_pairs(benchmark::State& state, std::size_t boxes, unsigned threads, bool spinner_on) {
    const busy_scene& scene = scene_of(boxes);
    const obbsat::collide_options options = options_for(threads);
    if (!same_pairs(obbsat::find_pairs(scene.poses, options), scene.pairs)) {
        state.SkipWithError("the pairs differ from those of one thread");
        return;
    }
    std::unique_ptr<core_spinner> spinner;
    if (spinner_on) {
        spinner = std::make_unique<core_spinner>();
    }
    std::size_t found = 0;
    for (auto _ : state) {
        const std::vector<obbsat::pair_index> pairs = obbsat::find_pairs(scene.poses, options);
        found = pairs.size();
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(found);
    state.counters["spinner_pinned"] = spinner && spinner->pinned() ? 1 : 0;
    state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(boxes));
}

}  // namespace

void register_busy_core_benchmarks() {
    constexpr std::size_t boxes = 1000000;
    for (const bool spinner_on : {false, true}) {
        for (const unsigned threads : {1u, 2u}) {
            const std::string name = "busy_core/local/poses/boxes:" + std::to_string(boxes) +
                                     "/sizes:uniform/threads:" + std::to_string(threads) +
                                     "/spinner:" + (spinner_on ? "on" : "off");
            benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
                busy_core_find_pairs(state, boxes, threads, spinner_on);
            })->Unit(benchmark::kMillisecond)->UseRealTime();
        }
    }
}

}  // namespace obbsat_bench
