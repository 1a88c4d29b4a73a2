// The accuracy report as text tables for a terminal: the oracle's classes per
// family (corner families, then pose families), one table per method and
// store (its store's families as rows), and a summary per method and store.
#pragma once

#include "accuracy/accuracy_report.hpp"

#include <cstdio>
#include <string>

namespace obbsat::accuracy {

/// An error rate for a table: "0" when there are no errors, else like "1.23e-04".
std::string format_rate(double rate);

/// How many pairs of each contact class every family holds, and every pose family.
void print_truth_table(std::FILE* out, const accuracy_report& report);

/// One table per method and store: errors per family of that store (FP, FN
/// touching, FN overlapping, error rate; for method exact also the share
/// settled on the slow path).
void print_method_tables(std::FILE* out, const accuracy_report& report);

/// One line per method and store: totals over every family of its store and Mpairs/s.
void print_summary(std::FILE* out, const accuracy_report& report);

}  // namespace obbsat::accuracy
