// The demo's table: a row per backend, store and thread count of each method,
// the groups of rows that must reproduce one reference, and how a row is
// timed (the median of checked runs after one warm-up).
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace obbsat::cli {

using demo_clock = std::chrono::steady_clock;

inline double seconds_since(demo_clock::time_point start) {
    return std::chrono::duration<double>(demo_clock::now() - start).count();
}

// One row of the table: a way to compute the scene's verdicts.
struct demo_entry {
    std::string runner;  // a backend's name, or whatever else computes the verdicts
    std::string store;   // how the rectangles are laid out in memory: soa, records or poses
    unsigned threads;
    std::function<void(std::uint8_t* verdicts)> run;
};

// The rows of one method on one kind of store, and the verdicts they must all
// reproduce: on corners the method on the scalar backend over soa at 1
// thread, on poses the method's scalar reference on poses called pair by pair.
struct demo_group {
    method test;
    store_kind kind;
    const char* reference_name;  // for the message when a row differs
    std::function<void(std::uint8_t* verdicts)> reference;
    std::vector<demo_entry> entries;  // the first is what 'speedup' compares against
};

// The scene, with its rectangles in every store the library takes for pair
// lists: arrays per coordinate, packed corner records (one cache line each),
// and packed poses (half a cache line each), built from the same corners.
struct demo_scene {
    scene world;
    rect_records records;
    pose_records poses;
};

// A row as measured, for the comparisons printed under the table.
struct measured_row {
    method test;
    std::string runner;
    std::string store;
    unsigned threads;
    double seconds;  // the median
};

/// The backends this CPU runs: scalar first, then narrowest to widest.
std::vector<backend> runnable_backends();

/// The corner test a method on poses is read beside: local is the article's
/// test taken into A's frame, so it stands beside sat4; conservative and exact
/// run on both kinds of store, so each stands beside itself.
method corner_counterpart(method m);

/// Every group the demo times for `methods`, each method's rows on corners
/// first, in the declaration order of each method's corner counterpart. The
/// rows refer to `demo`, which must outlive them.
std::vector<demo_group> demo_groups(const demo_scene& demo, const std::vector<method>& methods);

/// The row of `rows` with these fields, or nullptr.
const measured_row* find_row(const std::vector<measured_row>& rows, method test, const char* store,
                             const char* runner, unsigned threads);

/// The median of `values` (the mean of the middle two when their count is even).
double median_of(std::vector<double> values);

// The median time of `reps` runs of `run` after one warm-up, or nothing when
// `check`, called after every run, returns false; `prepare` runs before each
// run, untimed.
template <class Prepare, class Run, class Check>
std::optional<double> timed_median(unsigned reps, Prepare prepare, Run run, Check check) {
    std::vector<double> times;
    for (unsigned rep = 0; rep <= reps; ++rep) {
        prepare();
        const demo_clock::time_point start = demo_clock::now();
        run();
        const double elapsed = seconds_since(start);
        if (!check()) {
            return std::nullopt;
        }
        if (rep > 0) {  // rep 0 is the warm-up
            times.push_back(elapsed);
        }
    }
    return median_of(times);
}

}  // namespace obbsat::cli
