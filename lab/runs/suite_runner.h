#pragma once

// Running the registrations of a suite plan (eval/suite_plan.h) on one data
// set: every run on the reference's map from a ScanStore (one map per
// reference scan and map options, reused by all its pairs and starts), in
// the plan's order, each scored (eval/suite_score.h).

#include <map>
#include <string>
#include <vector>

#include "lab/eval/suite_plan.h"
#include "lab/eval/suite_score.h"
#include "lab/runs/matcher.h"
#include "lab/runs/pair_registration.h"
#include "mlndt/common/progress.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {

// One run's result: the scored outcome and the registration's own summary
// (its verdict, message, pose, fit and constraint evidence), not a copy of
// its fields.
struct SuiteRunResult {
  SuiteOutcome outcome;
  RegistrationSummary registration;
  PairTimes times;
};

// The options of one run: `options` with, for ML-NDT, the run's start
// uncertainty as the initial uncertainty when it is given.
MatcherOptions SuiteRunOptions(const MatcherOptions& options,
                               const SuiteRun& run);

// Runs `runs` (all of one data set) with `options`, scoring each with
// `criterion`. `scan_paths` maps every scan number the runs name to its
// file. Scans are read when first needed and released once no later run
// needs them; maps are built once per reference scan. Appends one result
// per run to *results, in order. `progress` (may be null, not owned) hears
// of each run once it is scored ("0_1 identity: CONVERGENCE right"). False with
// *error naming the file when a scan cannot be read or its map cannot be built
// (a registration FAILURE is a result, not an error).
bool RunSuiteDataset(const MatcherOptions& options,
                     const SuccessCriterion& criterion,
                     const std::map<int64_t, std::string>& scan_paths,
                     const std::vector<SuiteRun>& runs,
                     ProgressCallback* progress,
                     std::vector<SuiteRunResult>* results,
                     std::string* error);

}  // namespace mlndt
