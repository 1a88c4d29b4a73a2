// The accuracy report: every method's verdicts on every hard-case suite
// family, scored against the exact oracle, and every method's speed on a
// broadphase-like scene, so that speed can be weighed against error.
//
// A method is reported once per kind of store it runs on: the methods on
// corners (rect_records) on the corner families, scored against the exact
// oracle of quads; the methods on poses (pose_records: local, conservative,
// exact) on the pose families, scored against the exact pose oracle, and
// labelled "local (poses)" and so on. Both are timed on the same scene, its
// rects converted to poses for the methods on poses.
//
// Verdicts come from the fastest backend this CPU runs (every backend gives
// the same verdicts, so the choice only affects how long scoring takes).
// Errors are counted per contact class of the truth: a false positive is a
// collision reported for a separated pair; a false negative is a pair the
// oracle finds touching or overlapping that the method calls separated.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/oracle/contact.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace obbsat::accuracy {

/// How one method fared on a set of pairs.
struct error_counts {
    std::uint64_t pairs = 0;
    std::uint64_t false_positives = 0;     ///< said collide, truth separated
    std::uint64_t missed_touching = 0;     ///< said separated, truth touching
    std::uint64_t missed_overlapping = 0;  ///< said separated, truth overlapping
    std::uint64_t slow_path_pairs = 0;     ///< pairs method exact settled on its exact slow path

    std::uint64_t false_negatives() const { return missed_touching + missed_overlapping; }
    std::uint64_t errors() const { return false_positives + false_negatives(); }
    /// errors / pairs, 0 when there are no pairs.
    double error_rate() const;
    /// Adds another set's counts to these.
    void add(const error_counts& other);
};

/// The errors of `verdicts` (0 or 1 per pair) against the oracle's `truth`.
error_counts score_verdicts(const oracle::contact* truth, const std::uint8_t* verdicts,
                            std::size_t count);

/// The oracle's view of one family's suite.
struct family_truth {
    std::string name;
    std::uint64_t pairs = 0;
    std::uint64_t separated = 0;
    std::uint64_t touching = 0;
    std::uint64_t overlapping = 0;
};

/// The oracle's classes of `truth`, counted, under `name`.
family_truth truth_of(const std::string& name, const std::vector<oracle::contact>& truth);

/// A method on one kind of store: one row of the report.
struct method_on_store {
    method test = method::sat4;
    store_kind store = store_kind::corners;
};

/// The method's name on corners, e.g. "sat4"; with " (poses)" on poses, e.g. "local (poses)".
std::string method_label(const method_on_store& m);

/// One method on one kind of store, across every family of that store.
struct method_result {
    method test = method::sat4;
    store_kind store = store_kind::corners;
    /// In the order of accuracy_report::families (corners) or pose_families (poses).
    std::vector<error_counts> per_family;
    /// Speed of the one scoring run on each family (settings.threads threads):
    /// how much the family's boundary pairs cost the method (exact's slow path).
    std::vector<double> family_mpairs_per_second;
    error_counts total;
    double mpairs_per_second = 0.0;        ///< on the throughput scene (see accuracy_report)

    /// A label of its own (the double report's rows, drawn by the same plot);
    /// empty for the float report's rows.
    std::string name;

    /// `name` if set, else method_label of this row.
    std::string label() const { return name.empty() ? method_label({test, store}) : name; }
};

struct accuracy_settings {
    std::size_t pairs_per_family = 20000;
    std::uint64_t seed = 1;
    unsigned threads = 1;        ///< for the oracle and the scored verdicts; timing uses 1
    unsigned timing_reps = 11;   ///< timed runs per method after a warm-up; the median counts
    bool measure_speed = true;   ///< false leaves every mpairs_per_second at 0
};

/// The scene every method is timed on, as the report describes it.
struct throughput_scene {
    std::size_t rects = 131072;
    std::size_t pairs = 262144;
    const char* density = "typical";
    const char* store = "rect_records";
    /// Where the methods on poses run: the scene's rects as poses (pose_records::from_corners).
    const char* pose_store = "pose_records";
    const char* order = "indexed, sorted by first rectangle";
    unsigned threads = 1;
};

struct accuracy_report {
    accuracy_settings settings;
    backend used = backend::scalar;      ///< the backend that produced every verdict and time
    std::string cpu;                     ///< the CPU's model name as the OS reports it, or "unknown"
    throughput_scene timing_scene;
    std::vector<family_truth> families;       ///< in suites::all_families() order
    std::vector<family_truth> pose_families;  ///< in suites::all_pose_families() order
    /// methods_on(corners) in order, then methods_on(poses) in order.
    std::vector<method_result> methods;
};

/// The families the rows of store `s` are scored on: report.families or report.pose_families.
const std::vector<family_truth>& families_of(const accuracy_report& report, store_kind s);

/// The CPU's model name from /proc/cpuinfo, or "unknown".
std::string cpu_model_name();

/// Called after each family is scored: the family's index and the number of families.
using progress_fn = std::function<void(std::size_t done, std::size_t total)>;

/// Scores every method on every family and times every method; see the file comment.
accuracy_report measure_accuracy(const accuracy_settings& settings,
                                 const progress_fn& progress = nullptr);

/// Mpairs/s of each method in `methods` (same order) on the throughput scene,
/// on backend `use`, 1 thread: the median of `reps` timed runs after a warm-up.
/// Methods on corners run on the scene's rect_records, methods on poses on
/// the same rects as pose_records, over the same pairs.
std::vector<double> measure_throughput(const std::vector<method_on_store>& methods, backend use,
                                       unsigned reps, const throughput_scene& spec = {});

}  // namespace obbsat::accuracy
