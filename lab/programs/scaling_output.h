#pragma once

// mlndt_scaling's printed reports (the texts of
// lab/experiments/scaling_report.h): the table and the slopes on stdout,
// the broken solves on stderr.

#include <vector>

#include "lab/experiments/scaling_measure.h"

namespace mlndt {
namespace lab {

// The markdown table of the sizes on stdout.
void PrintScalingTable(const std::vector<SizeResult>& results);

// Prints the slope of every series and of the solve against the sampled
// points; returns the series' slopes.
std::vector<double> PrintScalingSlopes(const std::vector<size_t>& sizes,
                                       const std::vector<SizeResult>& results);

// Names on stderr every size whose solve failed or missed the motion by
// more than the tolerances.
void PrintBrokenSolves(const std::vector<SizeResult>& results,
                       double max_translation_error_m,
                       double max_rotation_error_deg);

}  // namespace lab
}  // namespace mlndt
