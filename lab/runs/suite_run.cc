#include "lab/runs/suite_run.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "lab/report/chained_progress.h"

namespace mlndt {

namespace fs = std::filesystem;

bool LoadSuiteDataset(const SuiteDataset& dataset,
                      size_t index,
                      const SuitePlanOptions& plan,
                      LoadedSuiteDataset* loaded,
                      std::string* error) {
  *loaded = LoadedSuiteDataset();
  loaded->dataset = dataset;
  std::error_code ec;
  if (!fs::is_directory(dataset.dir, ec)) {
    *error = dataset.dir + ": not a folder";
    return false;
  }
  const std::string pairs_path =
      (fs::path(dataset.dir) / "reference_pairs.json").string();
  if (!ReadReferencePairs(pairs_path, &loaded->pairs, error)) return false;
  DatasetScanFiles files;
  if (!ListDatasetScanFiles(dataset.dir, &files, error)) return false;
  loaded->runs =
      PlanDatasetRuns(plan, index, dataset.name, loaded->pairs, &loaded->skips);
  for (const SuiteRun& run : loaded->runs) {
    for (const int64_t number : {run.reference_index, run.input_index}) {
      if (loaded->scan_paths.count(number) > 0) continue;
      std::string path;
      if (!FindScanFile(files, number, &path, error)) {
        *error = dataset.dir + ": pair " + run.pair_key + ": " + *error;
        return false;
      }
      loaded->scan_paths[number] = path;
    }
  }
  return true;
}

std::string SuitePlanText(const std::vector<LoadedSuiteDataset>& datasets) {
  std::string out;
  size_t total = 0;
  for (const LoadedSuiteDataset& set : datasets) {
    char line[1024];
    std::snprintf(line,
                  sizeof(line),
                  "%s: %s, %zu reference pairs, %zu runs on %zu scans, right "
                  "within %g m and %g deg\n",
                  set.dataset.name.c_str(),
                  set.dataset.dir.c_str(),
                  set.pairs.size(),
                  set.runs.size(),
                  set.scan_paths.size(),
                  set.dataset.criterion.max_translation_m,
                  set.dataset.criterion.max_rotation_deg);
    out += line;
    total += set.runs.size();
  }
  return out + std::to_string(total) + " runs\n\n";
}

bool RunSuite(const MatcherOptions& options,
              const std::vector<LoadedSuiteDataset>& datasets,
              ProgressCallback* progress,
              std::vector<std::vector<SuiteRunResult>>* results,
              std::string* error) {
  size_t total = 0;
  for (const LoadedSuiteDataset& set : datasets) total += set.runs.size();
  ChainedProgress chained(progress, total);
  results->clear();
  for (const LoadedSuiteDataset& set : datasets) {
    chained.Next(set.dataset.name);
    results->emplace_back();
    if (!RunSuiteDataset(options,
                         set.dataset.criterion,
                         set.scan_paths,
                         set.runs,
                         &chained,
                         &results->back(),
                         error)) {
      *error = set.dataset.name + ": " + *error;
      return false;
    }
  }
  return true;
}

SuiteScore ScoreLoadedSuite(
    const std::vector<LoadedSuiteDataset>& loaded,
    const std::vector<std::vector<SuiteRunResult>>& results,
    const SuitePlanOptions& plan,
    double reach_share,
    size_t* runs) {
  std::vector<std::string> names;
  std::vector<SuiteSkips> skips;
  std::vector<SuiteOutcome> outcomes;
  for (size_t d = 0; d < loaded.size(); ++d) {
    names.push_back(loaded[d].dataset.name);
    skips.push_back(loaded[d].skips);
    for (const SuiteRunResult& r : results[d]) outcomes.push_back(r.outcome);
  }
  *runs = outcomes.size();
  return ScoreSuite(
      names, plan.starts, plan.offsets, skips, outcomes, reach_share);
}

}  // namespace mlndt
