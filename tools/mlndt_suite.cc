// mlndt_suite: scores a registration set against references (pairs × starts
// × options) and prints how right the results are and how honest the
// verdicts are (issue 12; docs/suite.md).
//
//   mlndt_suite --datasets=DIR[:tol_m:tol_deg],... [--data_dir=DIR]
//               [--starts=identity,prior,offsets,perturbed,constant_velocity]
//               [--offsets="x:0.5,2,5,10;yaw:10,30,45;xyyaw:3,3,20"]
//               [--steps=1,2,3,5,10] [--output_dir=DIR [--plot]]
//               [--fail_on=precision:0.995,recall:0.97,success:0.98]
//               [registration flags: --preset, --finest_cell_size, ...]
//
// Every data set folder holds a reference_pairs.json; its scans are in it
// or in pcd/, found by the digits of their file names. On the shared data
// (shared/data/README.md):
//
//   mlndt_suite --data_dir=shared/data --datasets=kitti00_frames_0000_0007,
//       mulran_kaist03_keyframes,3dtk_example_scans:0.1:1,
//       pcl_room_scans:0.1:1,koide3_velodyne_pair
//
// Prints the confusion table (right/wrong × TerminationType) with the
// precision and recall of CONVERGENCE and of usable results, the table per
// data set and start, the accuracy of the right runs from the identity and
// the prior, and the reach per offset. --output_dir writes runs.csv and
// summary.json (and quality.png with --plot). Exit codes (tool_main.h): 0
// after a complete run, 1 when the run misses a --fail_on target (or its
// outputs cannot be written), 2 on bad input (refused before any
// registration, naming the flag).

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "lab/eval/suite_report.h"
#include "lab/runs/suite_runner.h"
#include "tools/common/flag_utils.h"
#include "tools/common/gnuplot.h"
#include "tools/common/json_output.h"
#include "tools/common/list_flags.h"
#include "tools/common/output_files.h"
#include "tools/common/registration_flags.h"
#include "tools/common/suite_inputs.h"
#include "tools/common/suite_output.h"
#include "tools/common/suite_run.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"

// clang-format off
DEFINE_string(datasets, "",
              "Comma-separated data set folders DIR[:tol_m:tol_deg], each with a "
              "reference_pairs.json; scans in DIR or DIR/pcd. A run is right within tol "
              "(default 0.2 m, 1 deg) of the reference");
DEFINE_string(data_dir, "", "Folder the relative --datasets folders are in");
DEFINE_string(steps, "",
              "Comma-separated j - i of the pairs i_j kept (data sets with more than one "
              "pair); empty = all");
DEFINE_int32(max_pairs_per_set, 0,
             "At most this many pairs per data set, smallest steps first; 0 = all");
DEFINE_string(starts, "identity,prior,offsets",
              "Comma-separated starts: identity | prior (the pair's prior_from_input) | "
              "offsets (offset ∘ reference, --offsets) | perturbed (reference pushed off "
              "at random within --perturb, registered with that initial uncertainty) | "
              "constant_velocity (pair i->i+s starts from the reference of (i-s)->i)");
DEFINE_string(offsets, "x:0.5,2,5,10;y:0.5,2,5,10;yaw:10,30,45;xyyaw:3,3,20",
              "';'-separated AXES:values, AXES of x,y,z [m] and roll,pitch,yaw [deg] "
              "(together or '+'-joined); k axes take the values k at a time "
              "(xyyaw:3,3,20 = one offset); applied in the reference frame");
DEFINE_string(perturb, "0.5,5",
              "perturbed: bound of the random offsets translation_m,rotation_deg");
DEFINE_int32(perturb_count, 1, "perturbed: random starts per pair, >= 1");
DEFINE_uint64(perturb_seed, 1, "perturbed: seed of the random offsets");
DEFINE_string(prior_uncertainty, "",
              "prior: translation_m,rotation_deg passed as the initial uncertainty; "
              "empty = unknown");
DEFINE_double(reach_share, 0.9, "Reach: the share of right runs an offset needs, (0, 1]");
DEFINE_string(output_dir, "", "Folder for runs.csv, summary.json (and quality.png)");
DEFINE_bool(plot, false, "Write quality.png with gnuplot (needs --output_dir; exit 2 "
            "when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program (--plot)");
DEFINE_string(fail_on, "",
              "Targets MEASURE:minimum,... (success, precision, recall, usable_precision, "
              "usable_recall); exit 1 when one is missed");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_suite";

struct SuiteConfig {
  std::vector<SuiteDataset> datasets;
  SuitePlanOptions plan;
  MatcherOptions matcher;
  std::vector<SuiteTarget> targets;
};

bool HasStart(const SuitePlanOptions& plan, StartKind kind) {
  return std::find(plan.starts.begin(), plan.starts.end(), kind) !=
         plan.starts.end();
}

// Flags that only apply with a start kind, refused without it.
bool RefuseUnusedStartFlags(const SuitePlanOptions& plan, std::string* error) {
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
      (HasStart(plan, StartKind::PERTURBED) ||
       !FLAGS_prior_uncertainty.empty())) {
    *error =
        "--initial_uncertainty would be overridden by the start's own (the "
        "perturbed bound, --prior_uncertainty): leave it out";
    return false;
  }
  return true;
}

// A "translation_m,rotation_deg" pair flag.
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

bool ParseStarts(SuitePlanOptions* plan, std::string* error) {
  std::vector<std::string> items;
  plan->starts.clear();
  if (!tools::SplitList(FLAGS_starts, &items)) {
    *error = "--starts='" + FLAGS_starts + "': expected a comma-separated list";
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
    plan->starts.push_back(kind);
  }
  if (HasStart(*plan, StartKind::OFFSETS) &&
      !ParseStartOffsets(FLAGS_offsets, &plan->offsets, error)) {
    *error = "--offsets: " + *error;
    return false;
  }
  return RefuseUnusedStartFlags(*plan, error);
}

// The numeric plan flags, each checked under its own name.
bool ParseNumbers(SuitePlanOptions* plan, std::string* error) {
  StartUncertainty& prior = plan->prior_uncertainty;
  if (!ParseBound("perturb",
                  FLAGS_perturb,
                  &plan->perturb_translation_m,
                  &plan->perturb_rotation_deg,
                  error) ||
      (!FLAGS_prior_uncertainty.empty() && !ParseBound("prior_uncertainty",
                                                       FLAGS_prior_uncertainty,
                                                       &prior.translation_m,
                                                       &prior.rotation_deg,
                                                       error))) {
    return false;
  }
  prior.given = !FLAGS_prior_uncertainty.empty();
  plan->perturb_count = FLAGS_perturb_count;
  plan->perturb_seed = FLAGS_perturb_seed;
  std::vector<int> steps;
  if (!FLAGS_steps.empty() && !tools::ParseIntList(FLAGS_steps, &steps)) {
    *error = "--steps=" + FLAGS_steps + ": expected comma-separated integers";
    return false;
  }
  plan->steps.assign(steps.begin(), steps.end());
  const std::vector<std::pair<const char*, bool>> checks = {
      {"--perturb: bounds must be in [0, 1e4] m and [0, 180] deg",
       plan->perturb_translation_m >= 0.0 &&
           plan->perturb_rotation_deg >= 0.0 &&
           plan->perturb_translation_m <= 1e4 &&
           plan->perturb_rotation_deg <= 180.0},
      {"--prior_uncertainty: must be in [0, 1e4] m and [0, 180] deg",
       !prior.given ||
           (prior.translation_m >= 0.0 && prior.rotation_deg >= 0.0 &&
            prior.translation_m <= 1e4 && prior.rotation_deg <= 180.0)},
      {"--perturb_count must be >= 1", plan->perturb_count >= 1},
      {"--steps: a step must not be 0",
       std::count(steps.begin(), steps.end(), 0) == 0},
      {"--max_pairs_per_set must be >= 0", FLAGS_max_pairs_per_set >= 0}};
  for (const auto& [message, ok] : checks) {
    if (!ok) {
      *error = message;
      return false;
    }
  }
  plan->max_pairs_per_set = static_cast<size_t>(FLAGS_max_pairs_per_set);
  return true;
}

bool ParsePlan(SuitePlanOptions* plan, std::string* error) {
  if (!ParseStarts(plan, error) || !ParseNumbers(plan, error)) return false;
  if (!plan->IsValid(error)) {
    *error = "--starts: " + *error;
    return false;
  }
  return true;
}

bool ParseOutputFlags(std::string* error) {
  if (!(FLAGS_reach_share > 0.0 && FLAGS_reach_share <= 1.0)) {
    *error = "--reach_share must be in (0, 1]";
    return false;
  }
  if (FLAGS_plot && FLAGS_output_dir.empty()) {
    *error = "--plot needs --output_dir";
    return false;
  }
  if (!FLAGS_plot &&
      !tools::RefuseGivenFlags({"gnuplot"}, "needs --plot", error)) {
    return false;
  }
  if (FLAGS_plot && !tools::GnuplotAvailable(FLAGS_gnuplot)) {
    *error = "--plot: gnuplot ('" + FLAGS_gnuplot +
             "') does not run; install gnuplot-nox or leave out --plot";
    return false;
  }
  return true;
}

bool ParseConfig(SuiteConfig* config, std::string* error) {
  if (FLAGS_datasets.empty()) {
    *error = "--datasets is required (DIR[:tol_m:tol_deg],...)";
    return false;
  }
  std::error_code ec;
  if (!FLAGS_data_dir.empty() &&
      !std::filesystem::is_directory(FLAGS_data_dir, ec)) {
    *error = "--data_dir=" + FLAGS_data_dir + ": not a folder";
    return false;
  }
  if (!tools::ParseSuiteDatasets(
          FLAGS_datasets, FLAGS_data_dir, &config->datasets, error) ||
      !ParsePlan(&config->plan, error) ||
      !tools::MatcherOptionsFromFlags(&config->matcher, error) ||
      !ParseOutputFlags(error)) {
    return false;
  }
  if (config->matcher.method == Method::NDT &&
      !FLAGS_prior_uncertainty.empty()) {
    *error = "--prior_uncertainty does not apply to --method=ndt";
    return false;
  }
  if (!FLAGS_fail_on.empty() &&
      !ParseSuiteTargets(FLAGS_fail_on, &config->targets, error)) {
    *error = "--fail_on: " + *error;
    return false;
  }
  return true;
}

bool WriteOutputs(const SuiteConfig& config,
                  const std::vector<tools::LoadedSuiteDataset>& loaded,
                  const std::vector<std::vector<SuiteRunResult>>& results,
                  const SuiteScore& score,
                  const tools::SuiteRunInfo& info,
                  std::string* error) {
  const std::string& dir = FLAGS_output_dir;
  if (!tools::WriteSuiteRunsCsv(dir + "/runs.csv", loaded, results, error) ||
      !tools::WriteJsonFile(
          dir + "/summary.json", tools::SuiteSummaryJson(score, info), error)) {
    return false;
  }
  std::printf(
      "\nwritten: %s/runs.csv, %s/summary.json", dir.c_str(), dir.c_str());
  if (FLAGS_plot) {
    const bool mlndt = config.matcher.method == Method::MLNDT &&
                       config.matcher.mlndt.quality_check.enabled;
    if (!tools::WriteSuiteQualityPlot(
            FLAGS_gnuplot,
            dir,
            results,
            mlndt ? &config.matcher.mlndt.quality_check : nullptr,
            error)) {
      return false;
    }
    std::printf(", %s/quality.png", dir.c_str());
  }
  std::printf("\n");
  return true;
}

int Run() {
  SuiteConfig config;
  std::string error;
  if (!ParseConfig(&config, &error)) return tools::Refuse(kTool, error);
  std::vector<tools::LoadedSuiteDataset> loaded(config.datasets.size());
  for (size_t d = 0; d < config.datasets.size(); ++d) {
    if (!tools::LoadSuiteDataset(
            config.datasets[d], d, config.plan, &loaded[d], &error)) {
      return tools::Refuse(kTool, error);
    }
  }
  if (!FLAGS_output_dir.empty() &&
      !mlndt::tools::PrepareOutputDir("output_dir",
                                      FLAGS_output_dir,
                                      {"runs.csv", "summary.json"},
                                      &error)) {
    return tools::Refuse(kTool, error);
  }
  std::printf("%s", tools::SuitePlanText(loaded).c_str());
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<SuiteRunResult>> results;
  if (!tools::RunSuiteWithProgress(config.matcher, loaded, &results, &error)) {
    return tools::Fail(kTool, error);
  }

  std::vector<std::string> names;
  std::vector<SuiteSkips> skips;
  std::vector<SuiteOutcome> outcomes;
  for (size_t d = 0; d < loaded.size(); ++d) {
    names.push_back(loaded[d].dataset.name);
    skips.push_back(loaded[d].skips);
    for (const SuiteRunResult& r : results[d]) outcomes.push_back(r.outcome);
  }
  const SuiteScore score = ScoreSuite(names,
                                      config.plan.starts,
                                      config.plan.offsets,
                                      skips,
                                      outcomes,
                                      FLAGS_reach_share);
  tools::SuiteRunInfo info;
  info.method = MethodToString(config.matcher.method);
  info.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  info.missed_targets = MissedSuiteTargets(score.confusion, config.targets);
  std::printf("%s", FormatSuiteReport(score).c_str());
  std::printf(
      "\nwall time: %.1f s for %zu runs\n", info.wall_time_s, outcomes.size());
  if (!FLAGS_output_dir.empty() &&
      !WriteOutputs(config, loaded, results, score, info, &error)) {
    return tools::Fail(kTool, error);
  }
  for (const std::string& missed : info.missed_targets) {
    std::printf("target missed: %s\n", missed.c_str());
  }
  return info.missed_targets.empty() ? mlndt::tools::kExitOk
                                     : mlndt::tools::kExitFailed;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Scores registrations of data sets with reference_pairs.json "
          "(pairs × starts × options): the confusion table of right/wrong "
          "against the reported termination, accuracy and reach. See "
          "docs/suite.md.",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
