// The accuracy report as a plot: speed (Mpairs/s, linear) across, error rate
// (log scale) up, one labelled point per method and store (a method on poses
// is labelled e.g. "local (poses)"). A rate of zero has no place on a log
// scale, so methods without a single error sit on a dashed floor line one
// decade below the smallest rate the run could have measured (1 / pairs
// scored), marked "no errors".
//
// Every point is <circle class="point" data-method="LABEL" .../> and every
// label <text class="label" data-method="LABEL">, so the picture can be
// checked by a program as well as by eye.
#pragma once

#include "accuracy/accuracy_report.hpp"

#include <string>

namespace obbsat::accuracy {

/// The plot of `report` as a standalone SVG document.
std::string accuracy_svg(const accuracy_report& report);

}  // namespace obbsat::accuracy
