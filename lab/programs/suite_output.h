#pragma once

// mlndt_suite's files: runs.csv (one row per run), summary.json (the
// tables) and quality.png (the verdict's measures of right and wrong runs).

#include <string>
#include <vector>

#include "lab/eval/suite_score.h"
#include "lab/programs/suite_inputs.h"
#include "lab/runs/suite_runner.h"
#include "mlndt/registration/quality_check.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace lab {

// The header of runs.csv (its columns, in order).
std::string SuiteRunsCsvHeader();

// Writes runs.csv: one row per run of every data set, in run order
// (results[d][k] is the result of datasets[d].runs[k]).
bool WriteSuiteRunsCsv(const std::string& path,
                       const std::vector<LoadedSuiteDataset>& datasets,
                       const std::vector<std::vector<SuiteRunResult>>& results,
                       std::string* error);

// The run's facts for summary.json.
struct SuiteRunInfo {
  std::string method;  // MethodToString.
  double wall_time_s = 0.0;
  std::vector<std::string> missed_targets;
};

// summary.json (docs/json_schema.md, "mlndt_suite"): the schema header, then
// the scored tables.
tools::Json SuiteSummaryJson(const SuiteScore& score, const SuiteRunInfo& info);

// runs.csv and summary.json into `dir`, with `plot` quality.png
// (WriteSuiteQualityPlot, lab/report/suite_quality_plot.h; `quality_check`
// as there), and the line naming
// them on stdout.
bool WriteSuiteOutputs(const std::string& dir,
                       const std::vector<LoadedSuiteDataset>& loaded,
                       const std::vector<std::vector<SuiteRunResult>>& results,
                       const SuiteScore& score,
                       const SuiteRunInfo& info,
                       bool plot,
                       const std::string& gnuplot,
                       const QualityCheckOptions* quality_check,
                       std::string* error);

}  // namespace lab
}  // namespace mlndt
