#pragma once

// mlndt_suite's inputs: the --datasets list and the data sets it names,
// each with its reference pairs, its planned runs and the files of the
// scans those runs read, all checked before any registration runs.

#include <map>
#include <string>
#include <vector>

#include "lab/eval/reference_pairs.h"
#include "lab/eval/suite_plan.h"

namespace mlndt {
namespace tools {

// Parses "DIR[:tol_m:tol_deg],..." (the default tolerance is
// SuccessCriterion's). A relative DIR is taken inside `data_dir` when that
// is not empty. The data set's name is the folder's name (the last part
// of DIR); two with the same name are refused. False with *error naming
// the item (and the flag).
bool ParseSuiteDatasets(const std::string& text,
                        const std::string& data_dir,
                        std::vector<SuiteDataset>* datasets,
                        std::string* error);

// A data set ready to run.
struct LoadedSuiteDataset {
  SuiteDataset dataset;
  std::map<std::string, ReferencePair> pairs;  // reference_pairs.json.
  std::vector<SuiteRun> runs;                  // PlanDatasetRuns.
  SuiteSkips skips;
  std::map<int64_t, std::string> scan_paths;  // Every scan the runs read.
};

// Reads dir/reference_pairs.json, plans the runs and finds the file of
// every scan they read (FindScanFile). False with *error naming the data
// set and the problem.
bool LoadSuiteDataset(const SuiteDataset& dataset,
                      size_t index,
                      const SuitePlanOptions& plan,
                      LoadedSuiteDataset* loaded,
                      std::string* error);

}  // namespace tools
}  // namespace mlndt
