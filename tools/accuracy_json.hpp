// The accuracy report as JSON, every figure the text tables show and the
// settings that produced them, for plots and for comparing runs.
//
// Shape:
//   { "format": "obbsat-accuracy-1", "version", "seed", "pairs_per_family",
//     "threads", "backend", "cpu",
//     "throughput_scene": { "density", "rects", "pairs", "store", "order",
//                           "threads", "timed_runs" },
//     "families": [ { "name", "pairs", "separated", "touching", "overlapping" } ],
//     "methods": [ { "name", "mpairs_per_second" (null when not measured),
//                    "total": COUNTS,
//                    "families": [ COUNTS + "family" + "mpairs_per_second" (of the
//                                  one scoring run, "threads" threads) ] } ] }
//   COUNTS = { "pairs", "false_positives", "false_negatives",
//              "false_negatives_touching", "false_negatives_overlapping",
//              "errors", "error_rate", "slow_path_pairs" }
#pragma once

#include "accuracy_report.hpp"

#include <string>

namespace obbsat::accuracy {

/// The report as a JSON document (UTF-8, ends with a newline); `version` is the program's.
std::string accuracy_json(const accuracy_report& report, const std::string& version);

}  // namespace obbsat::accuracy
