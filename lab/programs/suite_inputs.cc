#include "lab/programs/suite_inputs.h"

#include <algorithm>
#include <filesystem>

#include "lab/report/gnuplot.h"
#include "lab/runs/suite_run.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"

namespace mlndt {
namespace lab {
namespace {

namespace fs = std::filesystem;

bool ParseDataset(const std::string& item,
                  const std::string& data_dir,
                  SuiteDataset* dataset,
                  std::string* error) {
  std::string dir = item;
  const size_t colon = item.find(':');
  if (colon != std::string::npos) {
    dir = item.substr(0, colon);
    std::vector<double> tolerances;
    const std::string rest = item.substr(colon + 1);
    std::string numbers = rest;
    for (char& c : numbers) c = c == ':' ? ',' : c;
    if (!tools::ParseNumberList(numbers, &tolerances) ||
        tolerances.size() != 2 || !(tolerances[0] > 0.0) ||
        !(tolerances[1] > 0.0)) {
      *error = "--datasets item '" + item +
               "': expected DIR or DIR:tol_m:tol_deg with tolerances > 0";
      return false;
    }
    dataset->criterion.max_translation_m = tolerances[0];
    dataset->criterion.max_rotation_deg = tolerances[1];
  }
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  if (dir.empty()) {
    *error = "--datasets item '" + item + "': no folder";
    return false;
  }
  dataset->name = fs::path(dir).filename().string();
  dataset->dir = data_dir.empty() || fs::path(dir).is_absolute()
                     ? dir
                     : (fs::path(data_dir) / dir).string();
  return true;
}

}  // namespace

bool ParseSuiteDatasets(const std::string& text,
                        const std::string& data_dir,
                        std::vector<SuiteDataset>* datasets,
                        std::string* error) {
  datasets->clear();
  std::error_code ec;
  if (!data_dir.empty() && !std::filesystem::is_directory(data_dir, ec)) {
    *error = "--data_dir=" + data_dir + ": not a folder";
    return false;
  }
  std::vector<std::string> items;
  if (!tools::SplitList(text, &items)) {
    *error = "--datasets='" + text +
             "': expected DIR[:tol_m:tol_deg],... (no empty item)";
    return false;
  }
  for (const std::string& item : items) {
    SuiteDataset dataset;
    if (!ParseDataset(item, data_dir, &dataset, error)) return false;
    for (const SuiteDataset& other : *datasets) {
      if (other.name == dataset.name) {
        *error = "--datasets: two data sets named '" + dataset.name +
                 "' (the folders' names must differ)";
        return false;
      }
    }
    datasets->push_back(dataset);
  }
  return true;
}

bool HasStart(const SuitePlanOptions& plan, StartKind kind) {
  return std::find(plan.starts.begin(), plan.starts.end(), kind) !=
         plan.starts.end();
}

bool RefuseUnusedStartFlags(const SuitePlanOptions& plan,
                            const std::string& prior_uncertainty,
                            std::string* error) {
  const std::vector<std::pair<StartKind, std::vector<std::string>>> flags = {
      {StartKind::OFFSETS, {"offsets"}},
      {StartKind::PERTURBED, {"perturb", "perturb_count", "perturb_seed"}},
      {StartKind::PRIOR, {"prior_uncertainty"}}};
  for (const auto& [kind, names] : flags) {
    const std::string reason =
        std::string("needs ") + StartKindToString(kind) + " in --starts";
    if (!HasStart(plan, kind) && !tools::RefuseGivenFlags(names, reason, error))
      return false;
  }
  if (tools::FlagGiven("initial_uncertainty") &&
      (HasStart(plan, StartKind::PERTURBED) || !prior_uncertainty.empty())) {
    *error =
        "--initial_uncertainty would be overridden by the start's own (the "
        "perturbed bound, --prior_uncertainty): leave it out";
    return false;
  }
  return true;
}

bool ParseBound(const char* flag,
                const std::string& text,
                double* translation_m,
                double* rotation_deg,
                std::string* error) {
  std::vector<double> v;
  if (!tools::ParseNumberList(text, &v) || v.size() != 2) {
    *error = std::string("--") + flag + "=" + text +
             ": expected translation_m,rotation_deg";
    return false;
  }
  *translation_m = v[0];
  *rotation_deg = v[1];
  return true;
}

bool LoadSuiteDatasets(const std::vector<SuiteDataset>& datasets,
                       const SuitePlanOptions& plan,
                       std::vector<LoadedSuiteDataset>* loaded,
                       std::string* error) {
  loaded->assign(datasets.size(), LoadedSuiteDataset());
  for (size_t d = 0; d < datasets.size(); ++d) {
    if (!LoadSuiteDataset(datasets[d], d, plan, &(*loaded)[d], error)) {
      *error = "--datasets '" + datasets[d].name + "': " + *error;
      return false;
    }
  }
  return true;
}

bool CheckSuitePlanBounds(const SuitePlanOptions& plan, std::string* error) {
  const StartUncertainty& prior = plan.prior_uncertainty;
  const std::vector<std::pair<const char*, bool>> checks = {
      {"--perturb: bounds must be in [0, 1e4] m and [0, 180] deg",
       plan.perturb_translation_m >= 0.0 && plan.perturb_rotation_deg >= 0.0 &&
           plan.perturb_translation_m <= 1e4 &&
           plan.perturb_rotation_deg <= 180.0},
      {"--prior_uncertainty: must be in [0, 1e4] m and [0, 180] deg",
       !prior.given ||
           (prior.translation_m >= 0.0 && prior.rotation_deg >= 0.0 &&
            prior.translation_m <= 1e4 && prior.rotation_deg <= 180.0)},
      {"--steps: a step must not be 0",
       std::count(plan.steps.begin(), plan.steps.end(), 0) == 0}};
  for (const auto& [message, ok] : checks) {
    if (!ok) {
      *error = message;
      return false;
    }
  }
  return true;
}

bool CheckSuiteOutputFlags(double reach_share,
                           bool plot,
                           const std::string& output_dir,
                           const std::string& gnuplot,
                           std::string* error) {
  if (!(reach_share > 0.0 && reach_share <= 1.0)) {
    *error = "--reach_share must be in (0, 1]";
    return false;
  }
  if (plot && output_dir.empty()) {
    *error = "--plot needs --output_dir";
    return false;
  }
  if (!plot && !tools::RefuseGivenFlags({"gnuplot"}, "needs --plot", error)) {
    return false;
  }
  if (plot && !GnuplotAvailable(gnuplot)) {
    *error = "--plot: gnuplot ('" + gnuplot +
             "') does not run; install gnuplot-nox or leave out --plot";
    return false;
  }
  return true;
}

bool ParseStartList(const std::string& text,
                    std::vector<StartKind>* starts,
                    std::string* error) {
  std::vector<std::string> items;
  starts->clear();
  if (!tools::SplitList(text, &items)) {
    *error = "--starts='" + text + "': expected a comma-separated list";
    return false;
  }
  for (const std::string& item : items) {
    StartKind kind;
    if (!StringToStartKind(item, &kind)) {
      *error = "--starts: '" + item +
               "': expected identity, prior, offsets, perturbed or "
               "constant_velocity";
      return false;
    }
    starts->push_back(kind);
  }
  return true;
}

}  // namespace lab
}  // namespace mlndt
