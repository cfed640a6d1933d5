#pragma once

// The registrations of the report: jobs (one configuration on some runs of
// one data set), run in order with one progress bar and its ETA on stderr,
// each run kept as a RunRecord (runs.csv holds them all).

#include <limits>
#include <string>
#include <vector>

#include "lab/eval/suite_plan.h"
#include "lab/experiments/configurations.h"
#include "lab/experiments/datasets.h"
#include "mlndt/common/progress.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace experiments {

struct Job {
  std::string experiment;  // "accuracy", "reach", "table9", "sampling".
  Configuration config;
  size_t dataset = 0;  // Index into the data sets.
  std::vector<SuiteRun> runs;
  // The experiment's varied value for every run of the job (the sampling
  // fraction, the start layer); NaN when none.
  double parameter = std::numeric_limits<double>::quiet_NaN();
};

// One registration's outcome.
struct RunRecord {
  std::string experiment;
  std::string dataset;
  std::string config;  // Configuration::key.
  std::string pair;    // "i_j".
  std::string start;   // SuiteRun::start.
  int offset_index = -1;
  double parameter = std::numeric_limits<double>::quiet_NaN();
  TerminationType termination = TerminationType::FAILURE;
  bool right = false;        // Within the data set's strict rule.
  bool paper_right = false;  // Translation error < 50 cm (Section 5.2.1).
  // The paper's Table 9 fail rule: > 1 m or > 15 deg from the reference.
  bool diverged = true;
  Vector6d paper_error = Vector6d::Zero();  // PaperAxesError.
  double translation_m = 0.0;
  double rotation_deg = 0.0;
  double time_ms = 0.0;  // Registration without the map build.
  int iterations = 0;
};

// A start of `pair` of data set `dataset`: the identity, the pair's prior,
// the reference pushed off by `offset` (offset ∘ reference), or c times the
// reference's parameters (the paper's Z_i = c Z_gt, Section 5.3). Rigid.
SuiteRun IdentityStart(size_t dataset,
                       const ExperimentDataset& set,
                       const std::string& pair);
SuiteRun PriorStart(size_t dataset,
                    const ExperimentDataset& set,
                    const std::string& pair);
SuiteRun OffsetStart(size_t dataset,
                     const ExperimentDataset& set,
                     const std::string& pair,
                     const StartOffset& offset,
                     int offset_index);
SuiteRun ScaledStart(size_t dataset,
                     const ExperimentDataset& set,
                     const std::string& pair,
                     double c);

// Runs every job in order, appending one record per run. `progress` (may be
// null, not owned) hears of every run, numbered across the jobs, its status
// led by the job's experiment, data set and configuration. False with *error
// naming the data set when a scan cannot be read.
bool RunJobs(const std::vector<ExperimentDataset>& datasets,
             const std::vector<Job>& jobs,
             ProgressCallback* progress,
             std::vector<RunRecord>* records,
             std::string* error);

// runs.csv: a header and one line per record.
std::string RunRecordsCsv(const std::vector<RunRecord>& records);

}  // namespace experiments
}  // namespace mlndt
