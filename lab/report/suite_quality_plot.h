#pragma once

// mlndt_suite's --plot: how the fit at the solution (FitQuality,
// mlndt/cost/fit_quality.h) separates right from wrong runs, drawn with
// gnuplot.

#include <string>
#include <vector>

#include "lab/runs/suite_runner.h"
#include "mlndt/registration/quality_check.h"

namespace mlndt {

// quality.png in `dir` (data and script in dir/plot_data): the share of
// right and of wrong runs at or below each value of the inlier fraction and
// of the median Mahalanobis distance (empirical distribution curves), with the
// quality check's thresholds as vertical lines (none when `check` is null:
// NDT). Runs without a fit (no points evaluated) are left out.
bool WriteSuiteQualityPlot(
    const std::string& gnuplot,
    const std::string& dir,
    const std::vector<std::vector<SuiteRunResult>>& results,
    const QualityCheckOptions* check,
    std::string* error);

}  // namespace mlndt
