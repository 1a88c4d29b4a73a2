// The double accuracy report (double_accuracy_report.hpp) as text tables in
// the float report's format: the double oracle's classes per family, one
// table per row, and a summary with a column for the pairs float32 cannot hold.
#pragma once

#include "accuracy/double_accuracy_report.hpp"

#include <cstdio>

namespace obbsat::accuracy {

/// The truth tables, the per-row tables and the summary.
void print_double_report(std::FILE* out, const double_accuracy_report& report);

}  // namespace obbsat::accuracy
