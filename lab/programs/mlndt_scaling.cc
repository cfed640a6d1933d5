// mlndt_scaling: measures how the three stages of a registration (map build,
// input sampling, solve) grow with the cloud size, on real scans, and fits
// time ∝ N^slope per stage.
//
//   mlndt_scaling [--scans=DIR --poses=FILE] [--sizes=10000,30000,...]
//                 [--repetitions=3] [--output_dir=OUT] [any mlndt_align
//                 registration flag]
//
// Data: every scan in --scans (sorted by file name) is moved into the first
// scan's frame with its ground-truth pose (P_0^-1 P_i, KITTI lines
// world_from_scan, one per scan; with --calib they are camera poses,
// converted as in mlndt_sequence) and the scans are merged into one cloud.
// The default is the bundled KITTI frames: 8 scans, 991,949 points, so the
// default sizes end at 990,000 rather than 1,000,000 (a size above the
// merged cloud is an error).
//
// For each size N in --sizes: the reference is a random subset of N points
// of the merged cloud and the input another, independently drawn subset of
// N points, both seeded from --seed (which also seeds the input sampling)
// and N. A subset keeps the merged cloud's order, i.e. scan-line order as a
// scanner delivers it, since point order matters to the caches. The input
// is moved by the inverse of --motion, so registering it from the identity
// must recover --motion as reference_from_input. Each registration is one
// mlndt::Register call that builds the reference map itself, and its
// RegistrationSummary gives the stage times; the same registration runs
// --repetitions times and the median time of each stage is reported.
// Finest-layer cells: one extra, untimed map build (ML-NDT only).
//
// Output: a markdown table on stdout, with per N the median map, sampling,
// solve and total times [ms], the sampled points, the occupied cells on the
// finest layer, the iterations and the error of the recovered transform
// against --motion; then the least-squares slope of log(time) against log(N)
// per stage. A registration that FAILs or ends farther than
// --max_translation_error / --max_rotation_error from --motion is flagged in
// the table and on stderr, and makes the exit code 1 (the times of a broken
// solve say nothing). With --output_dir: scaling.csv (the table),
// scaling.gp and scaling.png (log-log time against N per stage and total,
// with a dashed slope-1 line through the smallest N's total). Exit code 1 on
// bad flags or data (including a size larger than the merged cloud), and
// when gnuplot is missing or fails (scaling.csv is still written).

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cstdio>
#include <string>
#include <vector>

#include "lab/experiments/scaling_measure.h"
#include "lab/experiments/scaling_report.h"
#include "lab/programs/scaling_output.h"
#include "lab/report/gnuplot.h"
#include "lab/runs/matcher.h"
#include "lab/runs/merged_cloud.h"
#include "mlndt/common/pose.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/output_files.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(scans, MLNDT_DATA_DIR "/kitti/pcd",
              "Folder of scans (every point-cloud file in it, sorted by file name); default: "
              "the bundled KITTI frames");
DEFINE_string(poses, MLNDT_DATA_DIR "/kitti/poses_velo.txt",
              "KITTI poses, one line per scan (world_from_scan in the scans' frame)");
DEFINE_string(calib, "", "Optional KITTI calib.txt: --poses are camera poses, converted with "
              "its Tr line (V = Tr^-1 P Tr)");
DEFINE_string(sizes, "10000,30000,100000,300000,990000",
              "Cloud sizes N (points of the reference and of the input): strictly increasing "
              "positive integers, each at most the merged cloud's size (991949 for the bundled "
              "KITTI frames)");
DEFINE_int32(repetitions, 3, "Runs per size (>= 1); the median time of each stage is reported");
DEFINE_string(motion, "0.5,0.3,0,0,0,2",
              "Known reference_from_input motion tx,ty,tz [m],alpha,beta,gamma [deg] "
              "(R = Rx Ry Rz) the input is moved by; registration starts from the identity");
DEFINE_double(max_translation_error, 0.1,
              "A recovered motion farther than this [m] from --motion is a broken solve");
DEFINE_double(max_rotation_error, 0.5,
              "A recovered motion farther than this [deg] from --motion is a broken solve");
DEFINE_string(output_dir, "", "Folder for scaling.csv, scaling.gp and scaling.png (optional)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_scaling";

// --sizes, --repetitions, the tolerances, --seed, --motion and the
// registration flags; false with *error for a bad value.
bool ParseFlags(std::vector<size_t>* sizes,
                ScalingSettings* settings,
                Isometry3d* reference_from_input,
                MatcherOptions* options,
                std::string* error) {
  if (!tools::ParseSizes(FLAGS_sizes, sizes, error)) return false;
  if (FLAGS_repetitions < 1) {
    *error =
        "--repetitions=" + std::to_string(FLAGS_repetitions) + ": must be >= 1";
    return false;
  }
  if (!(FLAGS_max_translation_error > 0) || !(FLAGS_max_rotation_error > 0)) {
    *error = "--max_translation_error and --max_rotation_error must be > 0";
    return false;
  }
  std::vector<double> motion;
  if (!tools::ParseNumberList(FLAGS_motion, &motion) || motion.size() != 6) {
    *error = "--motion=" + FLAGS_motion +
             ": expected 6 comma-separated numbers tx,ty,tz "
             "[m],alpha,beta,gamma [deg]";
    return false;
  }
  settings->seed = tools::Uint64Flag("seed");
  settings->repetitions = FLAGS_repetitions;
  settings->max_translation_error_m = FLAGS_max_translation_error;
  settings->max_rotation_error_deg = FLAGS_max_rotation_error;
  *reference_from_input = PoseVectorToIsometry(PoseVectorFromDegrees(
      motion[0], motion[1], motion[2], motion[3], motion[4], motion[5]));
  return tools::MatcherOptionsFromFlags(options, error);
}

// scaling.csv and, when gnuplot is there, scaling.png into --output_dir.
int WriteOutputs(const MatcherOptions& options,
                 const std::vector<SizeResult>& results,
                 const std::vector<double>& slopes,
                 bool gnuplot_ok) {
  const std::string dir = FLAGS_output_dir;
  std::string error;
  if (!WriteScalingCsv(dir + "/scaling.csv", results, &error)) {
    return tools::Fail(kTool, error);
  }
  std::printf("\noutput: %s/scaling.csv", dir.c_str());
  if (!gnuplot_ok) {
    std::printf("\n");
    return tools::Fail(
        kTool,
        "scaling.png skipped: gnuplot ('" + FLAGS_gnuplot +
            "') not found; scaling.csv is written. Install gnuplot-nox");
  }
  if (!WriteScalingPlot(FLAGS_gnuplot,
                        dir,
                        ScalingPlotTitle(FLAGS_repetitions,
                                         options.method,
                                         tools::FlagText("backend"),
                                         tools::FlagText("sampling")),
                        results,
                        slopes,
                        &error)) {
    return tools::Fail(kTool, error);
  }
  std::printf(", scaling.gp, scaling.png\n");
  return 0;
}

int Run() {
  std::vector<size_t> sizes;
  ScalingSettings settings;
  Isometry3d reference_from_input;
  MatcherOptions options;
  std::string error;
  if (!ParseFlags(&sizes, &settings, &reference_from_input, &options, &error))
    return tools::Refuse(kTool, error);
  if (!FLAGS_output_dir.empty()) {
    if (!tools::PrepareOutputDir(
            "output_dir", FLAGS_output_dir, {"scaling.csv"}, &error)) {
      return tools::Refuse(kTool, error);
    }
  }
  const bool gnuplot_ok =
      GnuplotReadyForPlots(kTool,
                           !FLAGS_output_dir.empty(),
                           FLAGS_gnuplot,
                           "scaling.png will be skipped (install gnuplot-nox)");

  PointCloud merged;
  size_t num_scans = 0;
  if (!MergeScansInFirstFrame(
          FLAGS_scans, FLAGS_poses, FLAGS_calib, &merged, &num_scans, &error)) {
    return tools::Refuse(kTool, error);
  }
  if (sizes.back() > merged.size()) {
    return tools::Refuse(kTool,
                         "--sizes: " + std::to_string(sizes.back()) +
                             " points requested, but the " +
                             std::to_string(num_scans) + " scans of " +
                             FLAGS_scans + " merge into only " +
                             std::to_string(merged.size()) + " points");
  }

  std::vector<SizeResult> results;
  tools::ProgressPrinter progress(kTool);
  const bool measured = MeasureSizes(settings,
                                     options,
                                     merged,
                                     sizes,
                                     reference_from_input,
                                     &progress,
                                     &results,
                                     &error);
  progress.Finish();
  if (!measured) return tools::Fail(kTool, error);

  std::printf("merged cloud: %zu points from %zu scans (%s); %s\n\n",
              merged.size(),
              num_scans,
              FLAGS_scans.c_str(),
              ScalingRunLine(options.method,
                             tools::FlagText("backend"),
                             tools::FlagText("sampling"),
                             tools::IntFlag("num_threads"),
                             FLAGS_motion,
                             FLAGS_repetitions)
                  .c_str());
  lab::PrintScalingTable(results);
  const std::vector<double> slopes = lab::PrintScalingSlopes(sizes, results);
  if (!FLAGS_output_dir.empty()) {
    const int code = WriteOutputs(options, results, slopes, gnuplot_ok);
    if (code != 0) return code;
  }
  for (const SizeResult& r : results) {
    if (!r.ok) {
      lab::PrintBrokenSolves(
          results, FLAGS_max_translation_error, FLAGS_max_rotation_error);
      return tools::Fail(kTool,
                         "the solve did not recover --motion at every size: "
                         "its times are not representative (see the table's "
                         "last column)");
    }
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Times map build, sampling and solve of a registration against the "
          "cloud size on real scans.\n"
          "  mlndt_scaling [--sizes=10000,30000,100000,300000,990000] "
          "[--repetitions=3] [--output_dir=OUT]",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
