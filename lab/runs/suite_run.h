#pragma once

// Loading mlndt_suite's data sets, running them one after the other, the
// lines that say what will run, and their score.

#include <string>
#include <vector>

#include "lab/eval/suite_plan.h"
#include "lab/eval/suite_score.h"
#include "lab/runs/matcher.h"
#include "lab/runs/suite_runner.h"

namespace mlndt {

// Reads dataset.dir/reference_pairs.json, plans the runs (PlanDatasetRuns;
// `index` is the data set's place in the suite) and finds the file of every
// scan they read (FindScanFile). False with *error naming the folder, file
// or pair and the problem.
bool LoadSuiteDataset(const SuiteDataset& dataset,
                      size_t index,
                      const SuitePlanOptions& plan,
                      LoadedSuiteDataset* loaded,
                      std::string* error);

// One line per data set (folder, pairs, runs, scans, tolerance) and the
// total.
std::string SuitePlanText(const std::vector<LoadedSuiteDataset>& datasets);

// Runs every data set's runs (RunSuiteDataset) in order; (*results)[d]
// holds data set d's results. `progress` (may be null, not owned) hears of
// every run, numbered across the suite, its status led by the data set's
// name. False with *error naming the data set when one cannot run (an
// unreadable scan).
bool RunSuite(const MatcherOptions& options,
              const std::vector<LoadedSuiteDataset>& datasets,
              ProgressCallback* progress,
              std::vector<std::vector<SuiteRunResult>>* results,
              std::string* error);

// ScoreSuite of the runs of every loaded data set; *runs counts them.
SuiteScore ScoreLoadedSuite(
    const std::vector<LoadedSuiteDataset>& loaded,
    const std::vector<std::vector<SuiteRunResult>>& results,
    const SuitePlanOptions& plan,
    double reach_share,
    size_t* runs);

}  // namespace mlndt
