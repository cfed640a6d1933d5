#include "lab/runs/suite_runner.h"

#include <glog/logging.h>

#include <algorithm>

#include "lab/runs/scan_store.h"

namespace mlndt {

MatcherOptions SuiteRunOptions(const MatcherOptions& options,
                               const SuiteRun& run) {
  MatcherOptions run_options = options;
  if (options.method == Method::MLNDT && run.uncertainty.given) {
    InitialGuessUncertainty& u = run_options.mlndt.initial_uncertainty;
    u.given = true;
    u.translation_m = run.uncertainty.translation_m;
    u.rotation_deg = run.uncertainty.rotation_deg;
  }
  return run_options;
}

bool RunSuiteDataset(const MatcherOptions& options,
                     const SuccessCriterion& criterion,
                     const std::map<int64_t, std::string>& scan_paths,
                     const std::vector<SuiteRun>& runs,
                     ProgressCallback* progress,
                     std::vector<SuiteRunResult>* results,
                     std::string* error) {
  CHECK(results != nullptr);
  CHECK(error != nullptr);
  // The store holds the scans in scan-number order, so that releasing the
  // scans before a position frees the ones no later run needs.
  std::vector<std::string> paths;
  std::map<int64_t, size_t> position;
  for (const auto& [number, path] : scan_paths) {
    position[number] = paths.size();
    paths.push_back(path);
  }
  const auto at = [&](int64_t number) {
    const auto it = position.find(number);
    CHECK(it != position.end()) << "scan " << number << " has no file";
    return it->second;
  };
  // first_needed[k]: the smallest store position runs k.. read.
  std::vector<size_t> first_needed(runs.size() + 1, paths.size());
  for (size_t k = runs.size(); k-- > 0;) {
    first_needed[k] = std::min({first_needed[k + 1],
                                at(runs[k].reference_index),
                                at(runs[k].input_index)});
  }
  ScanStore store(paths);
  for (size_t k = 0; k < runs.size(); ++k) {
    const SuiteRun& run = runs[k];
    store.ReleaseBefore(first_needed[k]);
    SuiteRunResult result;
    const RegistrationSummary& summary = result.registration;
    if (!RegisterPair(SuiteRunOptions(options, run),
                      &store,
                      at(run.reference_index),
                      at(run.input_index),
                      run.initial_reference_from_input,
                      &result.registration,
                      &result.times,
                      error)) {
      return false;
    }
    result.outcome = ScoreSuiteRun(run,
                                   criterion,
                                   summary.termination_type,
                                   summary.reference_from_input,
                                   summary.total_time_s * 1e3);
    results->push_back(result);
    ReportProgress(progress,
                   {k,
                    k + 1,
                    runs.size(),
                    run.pair_key + " " + run.start + ": " +
                        TerminationTypeToString(result.outcome.termination) +
                        (result.outcome.right ? " right" : " wrong")});
  }
  return true;
}

}  // namespace mlndt
