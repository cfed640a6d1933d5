// mlndt_odometry: scan-to-local-map LiDAR odometry with ML-NDT over a folder
// of scans or a ROS 1 bag (mlndt/odometry/odometry.h has the method).
//
//   mlndt_odometry DIR_OR_BAG (or --scans=DIR [--times=FILE] | --bag=FILE)
//                  [--topic=NAME] [--output_dir=OUT] [--gt_poses=poses.txt
//                  [--poses_are_camera
//                  --calib=calib.txt]] [--max_scans=N] [odometry flags]
//                  [any mlndt_align registration flag]
//
// Each scan is predicted with constant velocity at its time stamp, deskewed
// when the bag has per-point times, and registered onto a local layered map
// of the last keyframes; the prediction's uncertainty (from how far recent
// predictions missed) sets the registration's initial_uncertainty and so
// its start layer. A scan not registered (its verdict is not CONVERGENCE)
// is searched for from wider starts; one that stays unregistered is flagged
// as a fallback in scans.csv, with its pose interpolated between the
// registered scans around it (extrapolated at the end). The odometry
// flags are OdometryOptions' fields (tools/cli/odometry_flags.h:
// --local_map_max_keyframes, --keyframes_min_translation_m,
// --prediction_max_translation_m, --gate_factor, --confirmation_enabled,
// ...).
//
// Writes into --output_dir: trajectory_kitti.txt, trajectory_tum.txt
// (stamped with the bag's header stamps or --times; else the scan indices,
// as its header line says), scans.csv and scans.json (every field of
// OdometryResultTable per scan: docs/json_schema.md), summary.json, and
// with --plots trajectory_xy.png. With --gt_poses (one world_from_sensor
// pose per scan): ATE after SE(3) alignment, RPE over
// --rpe_delta scans and the KITTI devkit's segment errors over
// --segment_lengths. Exit code 0 when every scan got a registered pose, 1
// when any scan fell back to its prediction (or on unreadable data, or
// missing gnuplot with --plots), 2 on bad flags (before any work).

#include <gflags/gflags.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "lab/eval/dataset.h"
#include "lab/report/gnuplot.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/odometry_flags.h"
#include "tools/cli/odometry_output.h"
#include "tools/cli/output_files.h"
#include "tools/cli/output_set.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/scan_input.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_int32(max_scans, 0, "Use only the first N scans (0 = all)");
DEFINE_string(output_dir, "", "Folder for the trajectories, scans.csv, summary.json and the plot");
DEFINE_string(gt_poses, "", "Optional KITTI reference poses, one line per scan (world_from_sensor)");
DEFINE_int32(rpe_delta, 100, "RPE: scans between the two poses of a motion (>= 1; shorter "
             "sequences use their length - 1)");
DEFINE_string(segment_lengths, "10,100", "KITTI devkit segment lengths [m], comma-separated");
DEFINE_bool(plots, true, "Write trajectory_xy.png with gnuplot (exit 1 when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_odometry";

bool OptionsFromFlags(OdometryOptions* options,
                      std::vector<double>* lengths,
                      std::string* error) {
  if ((FLAGS_scans.empty() && FLAGS_bag.empty()) || FLAGS_output_dir.empty()) {
    *error =
        "give the scans: a folder or a bag (or --scans=DIR, --bag=FILE) "
        "and --output_dir=DIR";
    return false;
  }
  if (FLAGS_max_scans < 0 || FLAGS_rpe_delta < 1) {
    *error = "--max_scans must be >= 0 and --rpe_delta >= 1";
    return false;
  }
  if (!tools::ParseNumberList(FLAGS_segment_lengths, lengths) ||
      std::any_of(lengths->begin(), lengths->end(), [](double v) {
        return !(v > 0);
      })) {
    *error = "--segment_lengths=" + FLAGS_segment_lengths +
             ": expected positive lengths [m], e.g. 10,100";
    return false;
  }
  if (!tools::RegistrationOptionsFromFlags(
          OdometryRegistrationOptions(), &options->registration, error) ||
      !tools::CheckCameraPoseFlags(
          "--gt_poses", !FLAGS_gt_poses.empty(), error)) {
    return false;
  }
  options->local_map.grid = options->registration.grid;
  if (!tools::OdometryFlags().Apply(options, error)) return false;
  if (!options->IsValid(error)) {
    *error = "odometry flags: " + *error;
    return false;
  }
  return true;
}

// The scans and the reference poses; every check before any work.
bool ReadInputs(tools::ScanInput* input,
                std::vector<Isometry3d>* reference,
                std::string* error) {
  if (!tools::ScanInputFromScansFlag(FLAGS_scans,
                                     {FLAGS_gt_poses, FLAGS_calib, FLAGS_times},
                                     static_cast<size_t>(FLAGS_max_scans),
                                     input,
                                     error) ||
      !input->ReadBagStamps(error)) {
    return false;
  }
  if (input->size() < 2) {
    *error =
        "odometry needs at least 2 scans, got " + std::to_string(input->size());
    return false;
  }
  if (FLAGS_gt_poses.empty()) return true;
  if (!ReadSequencePoses(FLAGS_gt_poses, FLAGS_calib, reference, error)) {
    *error = "--gt_poses: " + *error;
    return false;
  }
  return tools::CheckPoseCount("--gt_poses=" + FLAGS_gt_poses,
                               reference->size(),
                               input->size(),
                               FLAGS_max_scans,
                               error);
}

// trajectory_xy.png; exit code 1 when gnuplot is missing or fails.
int WritePlot(bool gnuplot_ok,
              const std::vector<OdometryResult>& results,
              const std::vector<Isometry3d>& reference) {
  if (!gnuplot_ok) {
    return tools::Fail(kTool, PlotSkippedMessage(FLAGS_gnuplot));
  }
  std::string error;
  if (!tools::WriteOdometryPlot(
          FLAGS_gnuplot, FLAGS_output_dir, results, reference, &error)) {
    return tools::Fail(kTool, error);
  }
  std::printf("plot: trajectory_xy.png\n");
  return 0;
}

int Run() {
  OdometryOptions options;
  std::vector<double> lengths;
  std::string error;
  if (!OptionsFromFlags(&options, &lengths, &error) ||
      !tools::CheckStartLayerBeforeMap(options.registration, &error)) {
    return tools::Refuse(kTool, error);
  }
  tools::ScanInput input;
  std::vector<Isometry3d> reference;
  if (!ReadInputs(&input, &reference, &error))
    return tools::Refuse(kTool, error);
  // Every file the run writes (a pose or times file there is refused).
  if (!tools::PrepareOutputDir("output_dir",
                               FLAGS_output_dir,
                               {"scans.csv",
                                "scans.json",
                                "summary.json",
                                "trajectory_kitti.txt",
                                "trajectory_tum.txt",
                                "trajectory_xy.png"},
                               &error) ||
      !tools::StartOutputSet(FLAGS_output_dir, &error)) {
    return tools::Refuse(kTool, error);
  }
  const bool gnuplot_ok = !FLAGS_plots || GnuplotAvailable(FLAGS_gnuplot);

  std::vector<OdometryResult> results;
  OdometrySummary summary;
  tools::ProgressPrinter progress(kTool, input.names());
  const bool ok = RunOdometry(options,
                              input.size(),
                              input.StampedLoader(),
                              &progress,
                              &results,
                              &summary,
                              &error);
  progress.Finish();
  if (!ok) return tools::Fail(kTool, error);

  OdometryMetrics metrics;
  const bool has_metrics = !reference.empty();
  if (has_metrics &&
      !ComputeOdometryMetrics(
          reference, results, FLAGS_rpe_delta, lengths, &metrics, &error)) {
    return tools::Fail(kTool, "metrics: " + error);
  }
  const OdometryMetrics* m = has_metrics ? &metrics : nullptr;
  if (!tools::WriteOdometryFiles(FLAGS_output_dir, input, results, &error)) {
    return tools::Fail(kTool, error);
  }
  tools::PrintOdometrySummary(summary, results, m);
  std::printf("output: %s\n", FLAGS_output_dir.c_str());
  const int plot = FLAGS_plots ? WritePlot(gnuplot_ok, results, reference) : 0;
  // summary.json last, naming the files written (output_set.h).
  std::vector<std::string> files = {
      "scans.csv", "scans.json", "trajectory_kitti.txt", "trajectory_tum.txt"};
  if (FLAGS_plots && plot == 0) files.push_back("trajectory_xy.png");
  if (!tools::FinishOutputSet(FLAGS_output_dir,
                              files,
                              tools::OdometrySummaryJson(summary, results, m),
                              &error)) {
    return tools::Fail(kTool, error);
  }
  if (plot != 0) return plot;
  if (!summary.AllUsable()) {
    return tools::Fail(kTool,
                       std::to_string(summary.fallbacks) +
                           " scan(s) have no registered pose (interpolated or "
                           "extrapolated, flagged in scans.csv)");
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  // --max_flatness, --weak_direction_rounds and --max_mean_score show the
  // odometry's defaults (OdometryRegistrationOptions).
  mlndt::tools::ShowRegistrationDefaults(mlndt::OdometryRegistrationOptions());
  if (!mlndt::tools::StartTool(
          "Scan-to-local-map LiDAR odometry with ML-NDT over a folder or a "
          "ROS 1 bag.\n"
          "  mlndt_odometry DIR_OR_BAG [--times=FILE] [--topic=NAME] "
          "[--output_dir=OUT] [--gt_poses=FILE]",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
