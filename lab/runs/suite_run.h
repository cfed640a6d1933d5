#pragma once

// Running mlndt_suite's data sets one after the other with a progress line
// (and its ETA) on stderr, and the lines that say what will run.

#include <string>
#include <vector>

#include "lab/eval/suite_plan.h"
#include "lab/eval/suite_score.h"
#include "lab/runs/matcher.h"
#include "lab/runs/suite_runner.h"

namespace mlndt {

// One line per data set (folder, pairs, runs, scans, tolerance) and the
// total.
std::string SuitePlanText(const std::vector<LoadedSuiteDataset>& datasets);

// Runs every data set's runs (RunSuiteDataset) in order; (*results)[d]
// holds data set d's results. False with *error naming the data set when
// one cannot run (an unreadable scan).
bool RunSuiteWithProgress(const MatcherOptions& options,
                          const std::vector<LoadedSuiteDataset>& datasets,
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
