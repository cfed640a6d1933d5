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
// merged cloud is an error). Near the top the two subsets share almost all
// their points; the geometry, and so the work per point, stays real.
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
// The finest layer's occupied cells come from one extra, untimed map build
// (ML-NDT only).
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

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "lab/eval/dataset.h"
#include "lab/eval/statistics.h"
#include "lab/runs/matcher.h"
#include "lab/runs/scan_store.h"
#include "mlndt/common/pose.h"
#include "tools/common/gnuplot.h"
#include "tools/common/list_flags.h"
#include "tools/common/output_files.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/scaling_measure.h"
#include "tools/common/scaling_report.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"

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

using tools::Fmt;
using tools::SizeResult;

int Fail(const std::string& message) {
  std::cerr << "mlndt_scaling: " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << "mlndt_scaling: " << message << std::endl;
  return tools::kExitUsage;
}

// Reads every scan, moves it into the first scan's frame with the ground
// truth and appends it to *merged.
bool LoadMergedCloud(PointCloud* merged,
                     size_t* num_scans,
                     std::string* error) {
  std::vector<std::string> paths;
  if (!ListScanFiles(FLAGS_scans, {FLAGS_poses, FLAGS_calib}, &paths, error))
    return false;
  std::vector<Isometry3d> world_from_scan;
  if (!ReadSequencePoses(FLAGS_poses, FLAGS_calib, &world_from_scan, error))
    return false;
  if (world_from_scan.size() < paths.size()) {
    *error = FLAGS_poses + " has " + std::to_string(world_from_scan.size()) +
             " poses for " + std::to_string(paths.size()) + " scans in " +
             FLAGS_scans;
    return false;
  }
  ScanStore store(paths);
  const Isometry3d first_from_world = world_from_scan[0].inverse();
  for (size_t i = 0; i < paths.size(); ++i) {
    const PointCloud* cloud = store.Cloud(i, error);
    if (cloud == nullptr) return false;
    const Isometry3d first_from_scan = first_from_world * world_from_scan[i];
    merged->Reserve(merged->size() + cloud->size());
    for (const Eigen::Vector3d& p : cloud->points())
      merged->Add(first_from_scan * p);
    store.ReleaseBefore(i + 1);
  }
  *num_scans = paths.size();
  return true;
}

// --sizes, --repetitions, the tolerances, --motion and the registration
// flags; false with *error for a bad value.
bool ParseFlags(std::vector<size_t>* sizes,
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
  *reference_from_input = PoseVectorToIsometry(PoseVectorFromDegrees(
      motion[0], motion[1], motion[2], motion[3], motion[4], motion[5]));
  return tools::MatcherOptionsFromFlags(options, error);
}

void PrintTable(const std::vector<SizeResult>& results) {
  std::printf(
      "| points | map ms | sampling ms | solve ms | total ms | sampled | "
      "finest-layer "
      "cells | layers | iterations | t error cm | r error deg | solve |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (const SizeResult& r : results) {
    std::printf(
        "| %zu | %s | %s | %s | %s | %zu | %zu | %d | %d | %s | %s | %s |\n",
        r.points,
        Fmt(r.map_ms, 1).c_str(),
        Fmt(r.sampling_ms, 1).c_str(),
        Fmt(r.solve_ms, 1).c_str(),
        Fmt(r.total_ms, 1).c_str(),
        r.sampled_points,
        r.finest_cells,
        r.num_layers,
        r.iterations,
        Fmt(r.translation_error_m * 100.0, 2).c_str(),
        Fmt(r.rotation_error_deg, 3).c_str(),
        r.ok ? "ok"
             : (r.termination == TerminationType::FAILURE ? "FAILED"
                                                          : "LARGE ERROR"));
  }
}

// Prints the slope of every series and of the solve against the sampled
// points; returns the series' slopes.
std::vector<double> PrintSlopes(const std::vector<size_t>& sizes,
                                const std::vector<SizeResult>& results) {
  std::printf(
      "\nlog-log slope over N = %zu..%zu (time ∝ N^slope; 1 = linear):\n",
      sizes.front(),
      sizes.back());
  std::vector<double> x;
  for (size_t n : sizes) x.push_back(static_cast<double>(n));
  std::vector<double> slopes;
  for (const auto& [name, values] : tools::Series(results)) {
    slopes.push_back(tools::LogLogSlope(x, values));
    std::printf(
        "  %-19s %s\n", (name + ":").c_str(), Fmt(slopes.back(), 2).c_str());
  }
  // The solve's cost per residual: its time against the sampled points.
  std::vector<double> sampled, solve_ms;
  for (const SizeResult& r : results) {
    sampled.push_back(static_cast<double>(r.sampled_points));
    solve_ms.push_back(r.solve_ms);
  }
  std::printf("  solve against sampled points (time ∝ S^slope): %s\n",
              Fmt(tools::LogLogSlope(sampled, solve_ms), 2).c_str());
  return slopes;
}

// scaling.csv and, when gnuplot is there, scaling.png into --output_dir.
int WriteOutputs(const MatcherOptions& options,
                 const std::vector<SizeResult>& results,
                 const std::vector<double>& slopes,
                 bool gnuplot_ok) {
  const std::string dir = FLAGS_output_dir;
  std::string error;
  if (!tools::WriteScalingCsv(dir + "/scaling.csv", results, &error)) {
    return Fail(error);
  }
  std::printf("\noutput: %s/scaling.csv", dir.c_str());
  if (!gnuplot_ok) {
    std::printf("\n");
    return Fail("scaling.png skipped: gnuplot ('" + FLAGS_gnuplot +
                "') not found; scaling.csv is written. Install gnuplot-nox");
  }
  const std::string title = "Registration time against cloud size (median of " +
                            std::to_string(FLAGS_repetitions) + " runs; " +
                            MethodToString(options.method) + ", " +
                            tools::FlagText("backend") + ", " +
                            tools::FlagText("sampling") + " sampling)";
  if (!tools::WriteScalingPlot(
          FLAGS_gnuplot, dir, title, results, slopes, &error)) {
    return Fail(error);
  }
  std::printf(", scaling.gp, scaling.png\n");
  return 0;
}

// Names every size whose solve failed or missed --motion; exit code 1.
int ReportBrokenSolves(const std::vector<SizeResult>& results) {
  for (const SizeResult& r : results) {
    if (r.ok) continue;
    std::cerr << "mlndt_scaling: N = " << r.points << ": "
              << (r.termination == TerminationType::FAILURE
                      ? "registration FAILED: " + r.message
                      : "recovered motion off by " +
                            Fmt(r.translation_error_m * 100.0, 2) + " cm, " +
                            Fmt(r.rotation_error_deg, 3) + " deg (tolerance " +
                            Fmt(FLAGS_max_translation_error * 100.0, 1) +
                            " cm, " + Fmt(FLAGS_max_rotation_error, 2) +
                            " deg)")
              << std::endl;
  }
  return Fail(
      "the solve did not recover --motion at every size: its times are not "
      "representative (see the table's last column)");
}

int Run() {
  std::vector<size_t> sizes;
  Isometry3d reference_from_input;
  MatcherOptions options;
  std::string error;
  if (!ParseFlags(&sizes, &reference_from_input, &options, &error)) {
    return Refuse(error);
  }
  if (!FLAGS_output_dir.empty()) {
    if (!tools::PrepareOutputDir(
            "output_dir", FLAGS_output_dir, {"scaling.csv"}, &error)) {
      return Refuse(error);
    }
  }
  const bool gnuplot_ok =
      FLAGS_output_dir.empty() || tools::GnuplotAvailable(FLAGS_gnuplot);
  if (!gnuplot_ok) {
    std::cerr
        << "mlndt_scaling: gnuplot ('" << FLAGS_gnuplot
        << "') not found: scaling.png will be skipped (install gnuplot-nox)\n";
  }

  PointCloud merged;
  size_t num_scans = 0;
  if (!LoadMergedCloud(&merged, &num_scans, &error)) return Refuse(error);
  if (sizes.back() > merged.size()) {
    return Refuse("--sizes: " + std::to_string(sizes.back()) +
                  " points requested, but the " + std::to_string(num_scans) +
                  " scans of " + FLAGS_scans + " merge into only " +
                  std::to_string(merged.size()) + " points");
  }

  tools::ScalingSettings settings;
  settings.seed = tools::Uint64Flag("seed");
  settings.repetitions = FLAGS_repetitions;
  settings.max_translation_error_m = FLAGS_max_translation_error;
  settings.max_rotation_error_deg = FLAGS_max_rotation_error;
  tools::Progress progress("mlndt_scaling", sizes.size());
  std::vector<SizeResult> results(sizes.size());
  for (size_t k = 0; k < sizes.size(); ++k) {
    if (!tools::MeasureSize(settings,
                            options,
                            merged,
                            sizes[k],
                            reference_from_input,
                            &results[k],
                            &error)) {
      progress.Finish();
      return Fail(error);
    }
    progress.Update(k + 1,
                    "N = " + std::to_string(sizes[k]) + ", total " +
                        Fmt(results[k].total_ms, 1) + " ms");
  }
  progress.Finish();

  std::printf(
      "merged cloud: %zu points from %zu scans (%s); %s, backend %s, sampling "
      "%s, "
      "threads %d; motion %s; median of %d runs\n\n",
      merged.size(),
      num_scans,
      FLAGS_scans.c_str(),
      MethodToString(options.method),
      tools::FlagText("backend").c_str(),
      tools::FlagText("sampling").c_str(),
      tools::IntFlag("num_threads"),
      FLAGS_motion.c_str(),
      FLAGS_repetitions);
  PrintTable(results);
  const std::vector<double> slopes = PrintSlopes(sizes, results);
  if (!FLAGS_output_dir.empty()) {
    const int code = WriteOutputs(options, results, slopes, gnuplot_ok);
    if (code != 0) return code;
  }
  for (const SizeResult& r : results) {
    if (!r.ok) return ReportBrokenSolves(results);
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
