// The accuracy report as JSON, every figure the text tables show and the
// settings that produced them, for plots and for comparing runs.
//
// Shape:
//   { "format": "obbsat-accuracy-2", "version", "seed", "pairs_per_family",
//     "threads", "backend", "cpu",
//     "throughput_scene": { "density", "rects", "pairs", "store", "pose_store",
//                           "order", "threads", "timed_runs" },
//     "families": [ FAMILY ], "pose_families": [ FAMILY ],
//     "methods": [ { "name", "store" ("corners" or "poses"), "label",
//                    "mpairs_per_second" (null when not measured),
//                    "total": COUNTS,
//                    "families": [ COUNTS + "family" + "mpairs_per_second" (of the
//                                  one scoring run, "threads" threads) ] } ] }
//   FAMILY = { "name", "pairs", "separated", "touching", "overlapping" }
//   COUNTS = { "pairs", "false_positives", "false_negatives",
//              "false_negatives_touching", "false_negatives_overlapping",
//              "errors", "error_rate", "slow_path_pairs" }
// A method's "families" are those of its store: "families" for corners,
// "pose_families" for poses. Format 1 had no pose rows, "pose_families",
// "store", "label" nor "pose_store".
#pragma once

#include "accuracy/accuracy_report.hpp"

#include <string>

namespace obbsat::accuracy {

/// The report as a JSON document (UTF-8, ends with a newline); `version` is the program's.
std::string accuracy_json(const accuracy_report& report, const std::string& version);

}  // namespace obbsat::accuracy
