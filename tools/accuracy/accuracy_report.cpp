#include "accuracy/accuracy_report.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/oracle/classify_pairs.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/scene.hpp>
#include <obbsat/suites/family.hpp>
#include <obbsat/suites/pose_family.hpp>
#include <obbsat/suites/pose_suite.hpp>
#include <obbsat/suites/suite.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>

namespace obbsat::accuracy {

std::string method_label(const method_on_store& m) {
    std::string label = method_name(m.test);
    if (m.store == store_kind::poses) {
        label += " (poses)";
    }
    return label;
}

const std::vector<family_truth>& families_of(const accuracy_report& report, store_kind s) {
    return s == store_kind::poses ? report.pose_families : report.families;
}

double error_counts::error_rate() const {
    return pairs == 0 ? 0.0 : static_cast<double>(errors()) / static_cast<double>(pairs);
}

void error_counts::add(const error_counts& other) {
    pairs += other.pairs;
    false_positives += other.false_positives;
    missed_touching += other.missed_touching;
    missed_overlapping += other.missed_overlapping;
    slow_path_pairs += other.slow_path_pairs;
}

error_counts score_verdicts(const oracle::contact* truth, const std::uint8_t* verdicts,
                            std::size_t count) {
    error_counts out;
    out.pairs = count;
    for (std::size_t i = 0; i < count; ++i) {
        const bool said_collide = verdicts[i] != 0;
        switch (truth[i]) {
            case oracle::contact::separated: out.false_positives += said_collide; break;
            case oracle::contact::touching: out.missed_touching += !said_collide; break;
            case oracle::contact::overlapping: out.missed_overlapping += !said_collide; break;
        }
    }
    return out;
}

namespace {

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace

family_truth truth_of(const std::string& name, const std::vector<oracle::contact>& truth) {
    family_truth out;
    out.name = name;
    out.pairs = truth.size();
    for (const oracle::contact c : truth) {
        out.separated += c == oracle::contact::separated;
        out.touching += c == oracle::contact::touching;
        out.overlapping += c == oracle::contact::overlapping;
    }
    return out;
}

std::string cpu_model_name() {
    std::ifstream info("/proc/cpuinfo");
    std::string line;
    while (std::getline(info, line)) {
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            if (colon != std::string::npos && colon + 2 <= line.size()) {
                return line.substr(colon + 2);
            }
        }
    }
    return "unknown";
}

std::vector<double> measure_throughput(const std::vector<method_on_store>& methods, backend use,
                                       unsigned reps, const throughput_scene& spec) {
    const scene world = make_scene(
        scene_spec_for(scene_density::typical, spec.rects, spec.pairs));
    const rect_records records(world.rects);
    const bool any_on_poses = std::any_of(methods.begin(), methods.end(), [](const method_on_store& m) {
        return m.store == store_kind::poses;
    });
    const pose_records poses = any_on_poses ? pose_records::from_corners(records) : pose_records();
    const std::size_t count = world.pairs.size();
    std::vector<std::uint8_t> verdicts(count);

    using clock = std::chrono::steady_clock;
    std::vector<double> speeds;
    for (const method_on_store& m : methods) {
        collide_options options;
        options.test = m.test;
        options.use = use;
        options.threads = spec.threads;
        std::vector<double> seconds;
        for (unsigned rep = 0; rep <= reps; ++rep) {
            const clock::time_point start = clock::now();
            if (m.store == store_kind::poses) {
                collide_pairs(poses, world.pairs.data(), count, verdicts.data(), options);
            } else {
                collide_pairs(records, world.pairs.data(), count, verdicts.data(), options);
            }
            const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
            if (rep > 0) {  // rep 0 warms caches and pages
                seconds.push_back(elapsed);
            }
        }
        speeds.push_back(static_cast<double>(count) / median_of(seconds) / 1e6);
    }
    return speeds;
}

namespace {

// Runs every row of `report` on `store` (rect_records or pose_records) over
// one family's pairs and adds its counts against `truth`.
template <class Store>
void score_rows(accuracy_report& report, store_kind kind, const Store& store,
                const std::vector<pair_index>& pairs, const std::vector<oracle::contact>& truth,
                std::vector<std::uint8_t>& verdicts) {
    const std::size_t count = pairs.size();
    verdicts.resize(count);
    for (method_result& result : report.methods) {
        if (result.store != kind) {
            continue;
        }
        std::size_t slow_path = 0;
        collide_options options;
        options.test = result.test;
        options.use = report.used;
        options.threads = report.settings.threads;
        options.slow_path_pairs = &slow_path;
        const auto start = std::chrono::steady_clock::now();
        collide_pairs(store, pairs.data(), count, verdicts.data(), options);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.family_mpairs_per_second.push_back(static_cast<double>(count) / seconds / 1e6);
        error_counts counts = score_verdicts(truth.data(), verdicts.data(), count);
        counts.slow_path_pairs = slow_path;
        result.per_family.push_back(counts);
        result.total.add(counts);
    }
}

}  // namespace

accuracy_report measure_accuracy(const accuracy_settings& settings, const progress_fn& progress) {
    accuracy_report report;
    report.settings = settings;
    report.used = best_supported_backend();
    report.cpu = cpu_model_name();
    std::vector<method_on_store> rows;
    for (const store_kind kind : {store_kind::corners, store_kind::poses}) {
        for (const method m : methods_on(kind)) {
            method_result result;
            result.test = m;
            result.store = kind;
            report.methods.push_back(result);
            rows.push_back({m, kind});
        }
    }

    const std::vector<suites::family>& families = suites::all_families();
    const std::vector<suites::pose_family>& pose_families = suites::all_pose_families();
    const std::size_t total = families.size() + pose_families.size();
    std::vector<oracle::contact> truth;
    std::vector<std::uint8_t> verdicts;
    for (std::size_t f = 0; f < families.size(); ++f) {
        const suites::suite s = suites::make_family(families[f], settings.seed,
                                                    settings.pairs_per_family);
        truth.resize(s.pairs.size());
        oracle::classify_pairs(s.rects.data(), s.rects.size(), s.pairs.data(), s.pairs.size(),
                               truth.data(), settings.threads);
        report.families.push_back(truth_of(suites::family_name(families[f]), truth));
        score_rows(report, store_kind::corners, rect_records(s.rects), s.pairs, truth, verdicts);
        if (progress) {
            progress(f + 1, total);
        }
    }
    for (std::size_t f = 0; f < pose_families.size(); ++f) {
        const suites::pose_suite s = suites::make_pose_family(pose_families[f], settings.seed,
                                                              settings.pairs_per_family);
        truth.resize(s.pairs.size());
        oracle::classify_pairs(s.poses.data(), s.poses.size(), s.pairs.data(), s.pairs.size(),
                               truth.data(), settings.threads);
        report.pose_families.push_back(truth_of(suites::pose_family_name(pose_families[f]), truth));
        score_rows(report, store_kind::poses, pose_records(s.poses), s.pairs, truth, verdicts);
        if (progress) {
            progress(families.size() + f + 1, total);
        }
    }

    if (settings.measure_speed) {
        const std::vector<double> speeds =
            measure_throughput(rows, report.used, settings.timing_reps, report.timing_scene);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            report.methods[i].mpairs_per_second = speeds[i];
        }
    }
    return report;
}

}  // namespace obbsat::accuracy
