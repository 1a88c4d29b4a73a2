#include "accuracy/double_accuracy_report.hpp"

#include "accuracy/double_families.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <cfloat>
#include <chrono>
#include <cmath>
#include <optional>

namespace obbsat::accuracy {

std::string double_method_result::label() const {
    return std::string(method_name(test)) + (float32 ? " (float32 " : " (double ") +
           (store == store_kind::poses ? "poses)" : "corners)");
}

const std::vector<family_truth>& families_of(const double_accuracy_report& report, store_kind s) {
    return s == store_kind::poses ? report.pose_families : report.corner_families;
}

namespace {

// `v` rounded to float, or nothing when it lies beyond float range (the
// conversion of such a double is undefined; a float store would refuse it).
std::optional<float> to_float(double v) {
    if (!(std::fabs(v) <= static_cast<double>(FLT_MAX))) {
        return std::nullopt;
    }
    return static_cast<float>(v);
}

std::optional<rect_pose> rounded(const rect_pose64& p) {
    const double values[6] = {p.center.x, p.center.y, p.half_extents.x, p.half_extents.y, p.rotation.x,
                              p.rotation.y};
    float f[6];
    for (int k = 0; k < 6; ++k) {
        const std::optional<float> v = to_float(values[k]);
        if (!v) {
            return std::nullopt;
        }
        f[k] = *v;
    }
    if (f[4] == 0.0f && f[5] == 0.0f) {
        return std::nullopt;  // the rotation vector rounded to (0, 0)
    }
    return rect_pose{{f[0], f[1]}, {f[2], f[3]}, {f[4], f[5]}};
}

std::optional<rect> rounded(const rect64& r) {
    const point64 corners[4] = {r.ul, r.ur, r.lr, r.ll};
    point p[4];
    for (int k = 0; k < 4; ++k) {
        const std::optional<float> x = to_float(corners[k].x);
        const std::optional<float> y = to_float(corners[k].y);
        if (!x || !y) {
            return std::nullopt;
        }
        p[k] = point{*x, *y};
    }
    return rect{p[0], p[1], p[2], p[3]};
}

// The pairs of a suite that float32 holds, rounded, with their truth.
template <class FloatShape>
struct float32_pairs {
    std::vector<FloatShape> shapes;
    std::vector<pair_index> pairs;
    std::vector<oracle::contact> truth;
    std::uint64_t dropped = 0;
};

template <class FloatShape, class Shape>
float32_pairs<FloatShape> rounded_pairs(const std::vector<Shape>& shapes, const std::vector<pair_index>& pairs,
                                        const std::vector<oracle::contact>& truth) {
    float32_pairs<FloatShape> out;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto a = rounded(shapes[pairs[i].a]);
        const auto b = rounded(shapes[pairs[i].b]);
        if (!a || !b) {
            ++out.dropped;
            continue;
        }
        const auto first = static_cast<std::uint32_t>(out.shapes.size());
        out.shapes.push_back(*a);
        out.shapes.push_back(*b);
        out.pairs.push_back(pair_index{first, first + 1});
        out.truth.push_back(truth[i]);
    }
    return out;
}

// Runs row `row` over `pairs` of `store` and adds its counts against `truth`;
// returns the run's seconds.
template <class Store>
double score_row(double_method_result& row, const Store& store, const std::vector<pair_index>& pairs,
                 const std::vector<oracle::contact>& truth, backend use, unsigned threads) {
    std::vector<std::uint8_t> verdicts(pairs.size());
    std::size_t slow_path = 0;
    collide_options options;
    options.test = row.test;
    options.use = use;
    options.threads = threads;
    options.slow_path_pairs = &slow_path;
    const auto start = std::chrono::steady_clock::now();
    collide_pairs(store, pairs.data(), pairs.size(), verdicts.data(), options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    error_counts counts = score_verdicts(truth.data(), verdicts.data(), pairs.size());
    counts.slow_path_pairs = slow_path;
    row.per_family.push_back(counts);
    row.total.add(counts);
    row.family_mpairs_per_second.push_back(seconds > 0 ? static_cast<double>(pairs.size()) / seconds / 1e6 : 0.0);
    return seconds;
}

}  // namespace

double_accuracy_report measure_double_accuracy(const accuracy_settings& settings, const progress_fn& progress) {
    double_accuracy_report report;
    report.settings = settings;
    report.used = best_supported_backend();
    report.cpu = cpu_model_name();
    for (const store_kind kind : {store_kind::poses, store_kind::corners}) {
        for (const method m : methods_on_doubles(kind)) {
            double_method_result row;
            row.test = m;
            row.store = kind;
            report.methods.push_back(row);
        }
        double_method_result contrast;
        contrast.test = method::exact;
        contrast.store = kind;
        contrast.float32 = true;
        report.methods.push_back(contrast);
    }
    std::vector<double> seconds(report.methods.size(), 0.0);

    const std::size_t pose_count = double_pose_family_names().size();
    const std::size_t total = pose_count + double_corner_family_names().size();
    for (std::size_t f = 0; f < pose_count; ++f) {
        const double_pose_suite s = make_double_pose_family(f, settings.seed, settings.pairs_per_family);
        const std::vector<oracle::contact> truth = double_truth(s);
        report.pose_families.push_back(truth_of(s.family, truth));
        const pose_records64 store(s.poses);
        const float32_pairs<rect_pose> rounded_set = rounded_pairs<rect_pose>(s.poses, s.pairs, truth);
        const pose_records float_store(rounded_set.shapes);
        for (std::size_t r = 0; r < report.methods.size(); ++r) {
            double_method_result& row = report.methods[r];
            if (row.store != store_kind::poses) {
                continue;
            }
            if (row.float32) {
                seconds[r] += score_row(row, float_store, rounded_set.pairs, rounded_set.truth, report.used,
                                        settings.threads);
            } else {
                seconds[r] += score_row(row, store, s.pairs, truth, report.used, settings.threads);
            }
            row.not_representable.push_back(row.float32 ? rounded_set.dropped : 0);
            row.total_not_representable += row.not_representable.back();
        }
        if (progress) {
            progress(f + 1, total);
        }
    }
    for (std::size_t f = 0; f < double_corner_family_names().size(); ++f) {
        const double_rect_suite s = make_double_corner_family(f, settings.seed, settings.pairs_per_family);
        const std::vector<oracle::contact> truth = double_truth(s);
        report.corner_families.push_back(truth_of(s.family, truth));
        const rect_records64 store(s.rects);
        const float32_pairs<rect> rounded_set = rounded_pairs<rect>(s.rects, s.pairs, truth);
        const rect_records float_store(rounded_set.shapes);
        for (std::size_t r = 0; r < report.methods.size(); ++r) {
            double_method_result& row = report.methods[r];
            if (row.store != store_kind::corners) {
                continue;
            }
            if (row.float32) {
                seconds[r] += score_row(row, float_store, rounded_set.pairs, rounded_set.truth, report.used,
                                        settings.threads);
            } else {
                seconds[r] += score_row(row, store, s.pairs, truth, report.used, settings.threads);
            }
            row.not_representable.push_back(row.float32 ? rounded_set.dropped : 0);
            row.total_not_representable += row.not_representable.back();
        }
        if (progress) {
            progress(pose_count + f + 1, total);
        }
    }
    for (std::size_t r = 0; r < report.methods.size(); ++r) {
        double_method_result& row = report.methods[r];
        row.mpairs_per_second =
            seconds[r] > 0 ? static_cast<double>(row.total.pairs) / seconds[r] / 1e6 : 0.0;
    }
    return report;
}

accuracy_report plotted_report(const double_accuracy_report& report) {
    accuracy_report plot;
    plot.settings = report.settings;
    plot.settings.measure_speed = true;
    plot.used = report.used;
    plot.cpu = report.cpu;
    plot.families = report.corner_families;
    plot.pose_families = report.pose_families;
    plot.timing_scene.density = "the double families'";
    plot.timing_scene.store = "rect_records64";
    plot.timing_scene.pose_store = "pose_records64";
    plot.timing_scene.order = "the scoring runs";
    plot.timing_scene.threads = report.settings.threads;
    std::uint64_t pairs = 0;
    for (const family_truth& f : report.pose_families) {
        pairs += f.pairs;
    }
    plot.timing_scene.pairs = pairs;
    plot.timing_scene.rects = 2 * pairs;
    for (const double_method_result& row : report.methods) {
        method_result m;
        m.test = row.test;
        m.store = row.store;
        m.name = row.label();
        m.per_family = row.per_family;
        m.family_mpairs_per_second = row.family_mpairs_per_second;
        m.total = row.total;
        m.mpairs_per_second = row.mpairs_per_second;
        plot.methods.push_back(m);
    }
    return plot;
}

}  // namespace obbsat::accuracy
