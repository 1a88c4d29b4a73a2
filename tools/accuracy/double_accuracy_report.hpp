// The accuracy report at double precision (`obbsat accuracy --precision
// double`): each method that runs on the double stores scored against the
// exact double oracle on each double family (accuracy/double_families.hpp),
// and, for contrast, float32 `exact` on the same pairs rounded to float32,
// scored against the same double truth: what a user gets who rounds double
// data to float before asking.
//
// Rows: exact, conservative and local on pose_records64 over the double pose
// families; exact and conservative on rect_records64 over the double corner
// families; exact on
// pose_records and on rect_records over the same pairs rounded to float32. A
// pair that float32 cannot hold (a value beyond float range, a rotation vector
// rounded to (0, 0)) is left out of the float32 row's counts and counted as
// not representable. Speed is the scoring runs' (every family's pairs, the
// settings' threads), as there is no double broadphase scene: boundary-heavy
// pairs, so exact's figure is its slow-path cost, not its scene speed.
#pragma once

#include "accuracy/accuracy_report.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace obbsat::accuracy {

/// One row of the double report.
struct double_method_result {
    method test = method::exact;
    store_kind store = store_kind::poses;
    bool float32 = false;  ///< the float32 method on the pairs rounded to float32
    /// In the order of double_accuracy_report::pose_families (poses) or corner_families.
    std::vector<error_counts> per_family;
    std::vector<double> family_mpairs_per_second;
    /// Pairs float32 cannot hold, per family (float32 rows; zero elsewhere).
    std::vector<std::uint64_t> not_representable;
    error_counts total;
    std::uint64_t total_not_representable = 0;
    double mpairs_per_second = 0.0;  ///< all its families' pairs over all their scoring runs' time

    /// E.g. "exact (double poses)", "conservative (double corners)", "exact (float32 poses)".
    std::string label() const;
};

struct double_accuracy_report {
    accuracy_settings settings;
    backend used = backend::scalar;  ///< the backend of every row
    std::string cpu;
    std::vector<family_truth> pose_families;    ///< double_pose_family_names() order
    std::vector<family_truth> corner_families;  ///< double_corner_family_names() order
    std::vector<double_method_result> methods;
};

/// The families a row is scored on.
const std::vector<family_truth>& families_of(const double_accuracy_report& report, store_kind s);

/// Scores every row on every family of its store; see the file comment. The
/// progress hears each family as it is done (pose families, then corner families).
double_accuracy_report measure_double_accuracy(const accuracy_settings& settings,
                                               const progress_fn& progress = nullptr);

/// The report in the shape the speed-against-error plot draws
/// (draw/accuracy_svg.hpp): one point per row, labelled as in the tables, its
/// speed the scoring runs'.
accuracy_report plotted_report(const double_accuracy_report& report);

}  // namespace obbsat::accuracy
