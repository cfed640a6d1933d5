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
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/common/pose.h"
#include "tools/common/gnuplot.h"
#include "tools/common/pair_evaluation.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/scan_store.h"
#include "tools/common/sequence_output.h"
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

int Fail(const std::string& message) {
  std::cerr << "mlndt_scaling: " << message << std::endl;
  return 1;
}

// Parses --sizes: strictly increasing positive integers.
bool ParseSizes(const std::string& text,
                std::vector<size_t>* sizes,
                std::string* error) {
  std::vector<double> values;
  if (!tools::ParseNumberList(text, &values) || values.empty()) {
    *error = "--sizes=" + text +
             ": expected comma-separated positive integers, e.g. 10000,30000";
    return false;
  }
  sizes->clear();
  for (double v : values) {
    if (!(v >= 1) || v != std::floor(v) || v > 1e12) {
      *error = "--sizes=" + text + ": '" + tools::Num(v) +
               "' is not a positive integer";
      return false;
    }
    const size_t n = static_cast<size_t>(v);
    if (!sizes->empty() && n <= sizes->back()) {
      *error = "--sizes=" + text + ": sizes must be strictly increasing (" +
               std::to_string(n) + " after " + std::to_string(sizes->back()) +
               ")";
      return false;
    }
    sizes->push_back(n);
  }
  return true;
}

// Reads every scan, moves it into the first scan's frame with the ground
// truth and appends it to *merged.
bool LoadMergedCloud(PointCloud* merged,
                     size_t* num_scans,
                     std::string* error) {
  std::vector<std::string> paths;
  if (!tools::ListScanFiles(
          FLAGS_scans, {FLAGS_poses, FLAGS_calib}, &paths, error))
    return false;
  std::vector<Isometry3d> world_from_scan;
  if (!tools::ReadSequencePoses(
          FLAGS_poses, FLAGS_calib, &world_from_scan, error))
    return false;
  if (world_from_scan.size() < paths.size()) {
    *error = FLAGS_poses + " has " + std::to_string(world_from_scan.size()) +
             " poses for " + std::to_string(paths.size()) + " scans in " +
             FLAGS_scans;
    return false;
  }
  tools::ScanStore store(paths);
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

// A uniform draw in [0, bound) without modulo bias, written out so that the
// same seed gives the same subsets on every standard library.
uint64_t UniformBelow(uint64_t bound, std::mt19937_64* rng) {
  const uint64_t limit = std::numeric_limits<uint64_t>::max() -
                         std::numeric_limits<uint64_t>::max() % bound;
  uint64_t draw;
  do {
    draw = (*rng)();
  } while (draw >= limit);
  return draw % bound;
}

// `n` distinct points of `cloud`, uniformly at random (partial Fisher-Yates),
// kept in the cloud's order.
PointCloud RandomSubset(const PointCloud& cloud, size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<size_t> index(cloud.size());
  for (size_t i = 0; i < index.size(); ++i) index[i] = i;
  for (size_t i = 0; i < n; ++i) {
    std::swap(index[i], index[i + UniformBelow(index.size() - i, &rng)]);
  }
  index.resize(n);
  std::sort(index.begin(), index.end());
  PointCloud subset;
  subset.Reserve(n);
  for (size_t i : index) subset.Add(cloud[i]);
  return subset;
}

// The measurements at one size.
struct SizeResult {
  size_t points = 0;
  double map_ms = 0.0;  // Medians over the repetitions.
  double sampling_ms = 0.0;
  double solve_ms = 0.0;
  double total_ms = 0.0;
  size_t sampled_points = 0;
  size_t finest_cells = 0;  // Occupied cells on the finest layer (0 for NDT).
  int num_layers = 0;
  int iterations = 0;
  TerminationType termination = TerminationType::FAILURE;
  std::string message;
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  bool ok = false;  // Not FAILURE, and within the error tolerances.
};

bool MeasureSize(const RegistrationOptions& options,
                 const PointCloud& merged,
                 size_t n,
                 const Isometry3d& reference_from_input,
                 SizeResult* result,
                 std::string* error) {
  *result = SizeResult();
  result->points = n;
  // Two independent subsets: seeds differ per size and per role.
  const uint64_t seed = FLAGS_seed * 0x9E3779B97F4A7C15ull + n;
  const PointCloud reference = RandomSubset(merged, n, seed * 2);
  const PointCloud input = TransformCloud(
      reference_from_input.inverse(), RandomSubset(merged, n, seed * 2 + 1));

  if (options.method == Method::MLNDT) {
    // Untimed, for the cell count (and a warm-up of the allocator).
    LayeredGrid grid;
    if (!LayeredGrid::Build(options.grid, reference, &grid, error)) {
      *error = "N = " + std::to_string(n) + ": map: " + *error;
      return false;
    }
    result->finest_cells = grid.layer_info().back().occupied_cells;
    result->num_layers = grid.num_layers();
  }

  std::vector<double> map_ms, sampling_ms, solve_ms, total_ms;
  RegistrationSummary summary;
  for (int r = 0; r < FLAGS_repetitions; ++r) {
    Register(options, reference, input, Isometry3d::Identity(), &summary);
    map_ms.push_back(summary.map_time_s * 1e3);
    sampling_ms.push_back(summary.sampling_time_s * 1e3);
    solve_ms.push_back(summary.solve_time_s * 1e3);
    total_ms.push_back(summary.total_time_s * 1e3);
  }
  result->map_ms = tools::ComputeStats(map_ms).median;
  result->sampling_ms = tools::ComputeStats(sampling_ms).median;
  result->solve_ms = tools::ComputeStats(solve_ms).median;
  result->total_ms = tools::ComputeStats(total_ms).median;
  // Registration is deterministic: the last run stands for all.
  result->sampled_points = summary.sampled_points;
  result->iterations = summary.num_iterations;
  if (summary.num_layers > 0) result->num_layers = summary.num_layers;
  result->termination = summary.termination_type;
  result->message = summary.message;
  result->translation_error_m =
      TranslationErrorM(reference_from_input, summary.reference_from_input);
  result->rotation_error_deg =
      RotationErrorRad(reference_from_input, summary.reference_from_input) *
      kRadToDeg;
  result->ok = summary.IsSolutionUsable() &&
               result->translation_error_m <= FLAGS_max_translation_error &&
               result->rotation_error_deg <= FLAGS_max_rotation_error;
  return true;
}

// Least-squares slope b of log(y) = a + b log(x); NaN with fewer than two
// points or a non-positive value.
double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 2 || x.size() != y.size()) return std::nan("");
  double mx = 0.0, my = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) return std::nan("");
    mx += std::log(x[i]);
    my += std::log(y[i]);
  }
  mx /= x.size();
  my /= x.size();
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

// The quantities whose slopes are reported, by name, one value per size.
std::vector<std::pair<std::string, std::vector<double>>> Series(
    const std::vector<SizeResult>& results) {
  std::vector<std::pair<std::string, std::vector<double>>> series = {
      {"map", {}},
      {"sampling", {}},
      {"solve", {}},
      {"total", {}},
      {"sampled points", {}},
      {"finest-layer cells", {}}};
  for (const SizeResult& r : results) {
    series[0].second.push_back(r.map_ms);
    series[1].second.push_back(r.sampling_ms);
    series[2].second.push_back(r.solve_ms);
    series[3].second.push_back(r.total_ms);
    series[4].second.push_back(static_cast<double>(r.sampled_points));
    series[5].second.push_back(static_cast<double>(r.finest_cells));
  }
  return series;
}

bool WriteCsv(const std::string& path,
              const std::vector<SizeResult>& results,
              std::string* error) {
  using tools::Num;
  std::ostringstream out;
  out << "points,map_ms,sampling_ms,solve_ms,total_ms,sampled_points,finest_"
         "layer_cells,"
         "num_layers,iterations,termination,translation_error_m,rotation_error_"
         "deg,ok\n";
  for (const SizeResult& r : results) {
    out << r.points << "," << Num(r.map_ms) << "," << Num(r.sampling_ms) << ","
        << Num(r.solve_ms) << "," << Num(r.total_ms) << "," << r.sampled_points
        << "," << r.finest_cells << "," << r.num_layers << "," << r.iterations
        << "," << TerminationTypeToString(r.termination) << ","
        << Num(r.translation_error_m) << "," << Num(r.rotation_error_deg) << ","
        << (r.ok ? 1 : 0) << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

// scaling.gp / scaling.png: log-log time against N, read from scaling.csv.
bool WritePlot(const std::string& dir,
               const RegistrationOptions& options,
               const std::vector<SizeResult>& results,
               const std::vector<double>& slopes,
               std::string* error) {
  const std::string csv = tools::GnuplotQuote(dir + "/scaling.csv");
  // The slope-1 line through the smallest size's total.
  const double per_point_ms =
      results.front().total_ms / static_cast<double>(results.front().points);
  std::ostringstream script;
  script
      << tools::GnuplotPngHeader(900, 600) << "set output "
      << tools::GnuplotQuote(dir + "/scaling.png") << "\n"
      << "set title 'Registration time against cloud size (median of "
      << FLAGS_repetitions << " runs; " << MethodToString(options.method)
      << ", " << BackendTypeToString(options.backend) << ", "
      << SamplingMethodToString(options.sampling.method) << " sampling)'\n"
      << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
      << "set xlabel 'points N (reference = input size)'\nset ylabel 'time "
         "[ms]'\n"
      << "set key inside top left\nset datafile separator ','\n"
      << "set xrange [" << tools::Num(results.front().points / 1.5) << ":"
      << tools::Num(results.back().points * 1.5) << "]\n"
      << "linear(x) = " << tools::Num(per_point_ms) << " * x\n"
      << "plot " << csv
      << " skip 1 using 1:2 with linespoints lw 2 pt 7 title 'map build (slope "
      << Fmt(slopes[0], 2) << ")', \\\n"
      << "     '' skip 1 using 1:3 with linespoints lw 2 pt 5 title 'sampling "
         "(slope "
      << Fmt(slopes[1], 2) << ")', \\\n"
      << "     '' skip 1 using 1:4 with linespoints lw 2 pt 9 title 'solve "
         "(slope "
      << Fmt(slopes[2], 2) << ")', \\\n"
      << "     '' skip 1 using 1:5 with linespoints lw 2 pt 11 title 'total "
         "(slope "
      << Fmt(slopes[3], 2) << ")', \\\n"
      << "     [" << tools::Num(static_cast<double>(results.front().points))
      << ":" << tools::Num(static_cast<double>(results.back().points))
      << "] linear(x) with lines dashtype 2 lc rgb 'gray40' lw 1.5 title "
         "'slope 1 (∝ N)'\n";
  return tools::RunGnuplot(
      FLAGS_gnuplot, dir + "/scaling.gp", script.str(), error);
}

int Run() {
  std::vector<size_t> sizes;
  std::string error;
  if (!ParseSizes(FLAGS_sizes, &sizes, &error)) return Fail(error);
  if (FLAGS_repetitions < 1) {
    return Fail("--repetitions=" + std::to_string(FLAGS_repetitions) +
                ": must be >= 1");
  }
  if (!(FLAGS_max_translation_error > 0) || !(FLAGS_max_rotation_error > 0)) {
    return Fail("--max_translation_error and --max_rotation_error must be > 0");
  }
  std::vector<double> motion;
  if (!tools::ParseNumberList(FLAGS_motion, &motion) || motion.size() != 6) {
    return Fail("--motion=" + FLAGS_motion +
                ": expected 6 comma-separated numbers tx,ty,tz "
                "[m],alpha,beta,gamma [deg]");
  }
  const Isometry3d reference_from_input =
      PoseVectorToIsometry(PoseVectorFromDegrees(
          motion[0], motion[1], motion[2], motion[3], motion[4], motion[5]));
  RegistrationOptions options;
  if (!tools::RegistrationOptionsFromFlags(&options, &error))
    return Fail(error);
  if (!FLAGS_output_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(FLAGS_output_dir, ec);
    if (ec) return Fail(FLAGS_output_dir + ": " + ec.message());
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
  if (!LoadMergedCloud(&merged, &num_scans, &error)) return Fail(error);
  if (sizes.back() > merged.size()) {
    return Fail("--sizes: " + std::to_string(sizes.back()) +
                " points requested, but the " + std::to_string(num_scans) +
                " scans of " + FLAGS_scans + " merge into only " +
                std::to_string(merged.size()) + " points");
  }

  tools::Progress progress("mlndt_scaling", sizes.size());
  std::vector<SizeResult> results(sizes.size());
  for (size_t k = 0; k < sizes.size(); ++k) {
    if (!MeasureSize(options,
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
      FLAGS_backend.c_str(),
      FLAGS_sampling.c_str(),
      options.num_threads,
      FLAGS_motion.c_str(),
      FLAGS_repetitions);
  std::printf(
      "| points | map ms | sampling ms | solve ms | total ms | sampled | "
      "finest-layer "
      "cells | layers | iterations | t error cm | r error deg | solve |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  bool all_ok = true;
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
    all_ok = all_ok && r.ok;
  }
  std::printf(
      "\nlog-log slope over N = %zu..%zu (time ∝ N^slope; 1 = linear):\n",
      sizes.front(),
      sizes.back());
  std::vector<double> x;
  for (size_t n : sizes) x.push_back(static_cast<double>(n));
  std::vector<double> slopes;
  for (const auto& [name, values] : Series(results)) {
    slopes.push_back(LogLogSlope(x, values));
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
              Fmt(LogLogSlope(sampled, solve_ms), 2).c_str());

  if (!FLAGS_output_dir.empty()) {
    const std::string dir = FLAGS_output_dir;
    if (!WriteCsv(dir + "/scaling.csv", results, &error)) return Fail(error);
    std::printf("\noutput: %s/scaling.csv", dir.c_str());
    if (!gnuplot_ok) {
      std::printf("\n");
      return Fail("scaling.png skipped: gnuplot ('" + FLAGS_gnuplot +
                  "') not found; scaling.csv is written. Install gnuplot-nox");
    }
    if (!WritePlot(dir, options, results, slopes, &error)) return Fail(error);
    std::printf(", scaling.gp, scaling.png\n");
  }
  if (!all_ok) {
    for (const SizeResult& r : results) {
      if (r.ok) continue;
      std::cerr << "mlndt_scaling: N = " << r.points << ": "
                << (r.termination == TerminationType::FAILURE
                        ? "registration FAILED: " + r.message
                        : "recovered motion off by " +
                              Fmt(r.translation_error_m * 100.0, 2) + " cm, " +
                              Fmt(r.rotation_error_deg, 3) +
                              " deg (tolerance " +
                              Fmt(FLAGS_max_translation_error * 100.0, 1) +
                              " cm, " + Fmt(FLAGS_max_rotation_error, 2) +
                              " deg)")
                << std::endl;
    }
    return Fail(
        "the solve did not recover --motion at every size: its times are not "
        "representative (see the table's last column)");
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "Times map build, sampling and solve of a registration against the cloud "
      "size on real "
      "scans.\n"
      "  mlndt_scaling [--sizes=10000,30000,100000,300000,990000] "
      "[--repetitions=3] "
      "[--output_dir=OUT]");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  if (argc > 1) {
    std::cerr << "mlndt_scaling: unexpected argument '" << argv[1]
              << "' (flags are --name=value)\n";
    return 1;
  }
  return mlndt::Run();
}
