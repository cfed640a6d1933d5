// mlndt_suite: scores a registration set against references (pairs × starts
// × options) and prints how right the results are and how honest the
// verdicts are (issue 12; docs/suite.md).
//
//   mlndt_suite --datasets=DIR[:tol_m:tol_deg],... [--data_dir=DIR]
//               [--starts=identity,prior,offsets,perturbed,constant_velocity]
//               [--offsets="x:0.5,2,5,10;yaw:10,30,45;xyyaw:3,3,20"]
//               [--steps=1,2,3,5,10] [--output_dir=DIR [--plot]]
//               [--fail_on=precision:0.995,recall:0.97,success:0.98]
//               [registration flags: --preset, --finest_cell_size_m, ...]
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

#include "lab/eval/suite_report.h"
#include "lab/programs/suite_inputs.h"
#include "lab/programs/suite_output.h"
#include "lab/report/gnuplot.h"
#include "lab/runs/suite_run.h"
#include "lab/runs/suite_runner.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/output_files.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/suite_plan_flags.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(datasets, "",
              "Comma-separated data set folders DIR[:tol_m:tol_deg], each with a "
              "reference_pairs.json; scans in DIR or DIR/pcd. A run is right within tol "
              "(default 0.2 m, 1 deg) of the reference");
DEFINE_string(data_dir, "", "Folder the relative --datasets folders are in");
DEFINE_string(steps, "",
              "Comma-separated j - i of the pairs i_j kept (data sets with more than one "
              "pair); empty = all");
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

bool ParseStarts(SuitePlanOptions* plan, std::string* error) {
  if (!lab::ParseStartList(FLAGS_starts, &plan->starts, error)) {
    return false;
  }
  if (lab::HasStart(*plan, StartKind::OFFSETS) &&
      !ParseStartOffsets(FLAGS_offsets, &plan->offsets, error)) {
    *error = "--offsets: " + *error;
    return false;
  }
  return lab::RefuseUnusedStartFlags(*plan, FLAGS_prior_uncertainty, error);
}

// The numeric plan flags, each checked under its own name.
bool ParseNumbers(SuitePlanOptions* plan, std::string* error) {
  StartUncertainty& prior = plan->prior_uncertainty;
  if (!lab::ParseBound("perturb",
                       FLAGS_perturb,
                       &plan->perturb_translation_m,
                       &plan->perturb_rotation_deg,
                       error) ||
      (!FLAGS_prior_uncertainty.empty() &&
       !lab::ParseBound("prior_uncertainty",
                        FLAGS_prior_uncertainty,
                        &prior.translation_m,
                        &prior.rotation_deg,
                        error))) {
    return false;
  }
  prior.given = !FLAGS_prior_uncertainty.empty();
  std::vector<int> steps;
  if (!FLAGS_steps.empty() && !tools::ParseIntList(FLAGS_steps, &steps)) {
    *error = "--steps=" + FLAGS_steps + ": expected comma-separated integers";
    return false;
  }
  plan->steps.assign(steps.begin(), steps.end());
  return lab::CheckSuitePlanBounds(*plan, error) &&
         tools::SuitePlanFlags().Apply(plan, error);
}

bool ParsePlan(SuitePlanOptions* plan, std::string* error) {
  if (!ParseStarts(plan, error) || !ParseNumbers(plan, error)) return false;
  if (!plan->IsValid(error)) {
    *error = "--starts: " + *error;
    return false;
  }
  return true;
}

bool ParseConfig(SuiteConfig* config, std::string* error) {
  if (FLAGS_datasets.empty()) {
    *error = "--datasets is required (DIR[:tol_m:tol_deg],...)";
    return false;
  }
  if (!lab::ParseSuiteDatasets(
          FLAGS_datasets, FLAGS_data_dir, &config->datasets, error) ||
      !ParsePlan(&config->plan, error) ||
      !tools::MatcherOptionsFromFlags(&config->matcher, error) ||
      !lab::CheckSuiteOutputFlags(FLAGS_reach_share,
                                  FLAGS_plot,
                                  FLAGS_output_dir,
                                  FLAGS_gnuplot,
                                  error)) {
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

int Run() {
  SuiteConfig config;
  std::string error;
  if (!ParseConfig(&config, &error)) return tools::Refuse(kTool, error);
  std::vector<LoadedSuiteDataset> loaded;
  if (!lab::LoadSuiteDatasets(config.datasets, config.plan, &loaded, &error)) {
    return tools::Refuse(kTool, error);
  }
  if (!FLAGS_output_dir.empty() &&
      !mlndt::tools::PrepareOutputDir("output_dir",
                                      FLAGS_output_dir,
                                      {"runs.csv", "summary.json"},
                                      &error)) {
    return tools::Refuse(kTool, error);
  }
  std::printf("%s", SuitePlanText(loaded).c_str());
  std::fflush(stdout);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<SuiteRunResult>> results;
  tools::ProgressPrinter progress(kTool);
  const bool ok = RunSuite(config.matcher, loaded, &progress, &results, &error);
  progress.Finish();
  if (!ok) return tools::Fail(kTool, error);

  size_t runs = 0;
  const SuiteScore score =
      ScoreLoadedSuite(loaded, results, config.plan, FLAGS_reach_share, &runs);
  lab::SuiteRunInfo info;
  info.method = MethodToString(config.matcher.method);
  info.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  info.missed_targets = MissedSuiteTargets(score.confusion, config.targets);
  std::printf("%s", FormatSuiteReport(score).c_str());
  std::printf("\nwall time: %.1f s for %zu runs\n", info.wall_time_s, runs);
  const bool mlndt = config.matcher.method == Method::MLNDT &&
                     config.matcher.mlndt.quality_check.enabled;
  if (!FLAGS_output_dir.empty() &&
      !lab::WriteSuiteOutputs(
          FLAGS_output_dir,
          loaded,
          results,
          score,
          info,
          FLAGS_plot,
          FLAGS_gnuplot,
          mlndt ? &config.matcher.mlndt.quality_check : nullptr,
          &error)) {
    return tools::Fail(kTool, error);
  }
  for (const std::string& missed : info.missed_targets) {
    std::printf("target missed: %s\n", missed.c_str());
  }
  return info.missed_targets.empty() ? tools::kExitOk : tools::kExitFailed;
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
