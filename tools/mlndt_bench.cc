// mlndt_bench: times solver choices on real scan pairs with references and
// reports speed and accuracy per configuration.
//
//   mlndt_bench [--data_dir=FOLDER_WITH_reference_pairs.json]
//               [--starts=identity,prior,offsets] [--offsets=...]
//               [--max_pairs=N] [--minimizers=trust_region,bfgs,lbfgs]
//               [--jacobians=autodiff,analytic] [--losses=none,huber,cauchy]
//               [--loss_scales=1.5] [--output_plot=FILE.png]
//   mlndt_bench [--pairs=koide3,kitti] [--defaults=current]
//               [--backends=ceres,newton,lm]
//   [--samplings=gbs]
//               [--gbs_cell_sizes=1]
//               [--start_layers=1] [--linear_solvers=dense_normal_cholesky]
//               [--trust_regions=levenberg_marquardt] [--threads=1]
//               [--repetitions=5]
//               [--compare_pcl] [--output_csv=FILE]
//
// Pairs: the pairs of any folder with a reference_pairs.json (--data_dir),
// else koide3 (the bundled Velodyne pair) and kitti (frame gaps of the
// bundled KITTI frames), each from every start of --starts; see
// tools/common/bench_pairs.h. Rows group the pairs by set and start kind.
//
// The grid is defaults x backends x samplings (x GBS cell sizes for gbs) x
// start layers x losses x loss scales x threads, and for the Ceres backend
// also x minimizers (trust region, or line search with BFGS or LBFGS
// directions) x Jacobians (auto-diff, or the analytic
// mlndt_point_cost_analytic.h of the same residual) x, for the trust
// region, linear solvers x trust-region strategies.
//
// nees: per usable run e^T P^-1 e, e the pose-vector difference estimate -
// reference, P = RegistrationSummary::covariance (lab/eval/nees.h; 6 when P
// is consistent with the errors against the references); its mean and
// median per row. --output_plot writes FILE (PNG), FILE.dat and FILE.gp:
// per set, median time against mean translation error, one point per
// configuration, the Pareto front (no other configuration both faster and
// more accurate) joined and labelled. Each repetition round runs every
// configuration once on every pair, alternating configurations pair by pair and
// rotating their order from round to round, so that machine noise hits all
// configurations alike. With
// --compare_pcl (built with -DMLNDT_WITH_PCL=ON)
// pcl::NormalDistributionsTransform takes part in the same rotation: a 0.1 m
// VoxelGrid on both clouds and 1.0 m cells as its peers (PEERS.md 1a), at most
// 35 iterations, and the --pcl_* flags' defaults step size 1.0 and
// transformation epsilon 1e-4, the PCL setting that reached the pairs' answers
// in our sweep (docs/performance.md). The peers' and PCL tutorial's step 0.1
// and epsilon 0.01 are a different thing since PCL PR #1724 (2017; Debian 12
// has PCL 1.13): NDT compares epsilon with the step's *squared* translation, so
// with steps capped at 0.1 m PCL stops after its first step (0.41 m short on
// the koide3 pair); with epsilon 1e-4 and step 0.1 it stops after 5 steps,
// still 0.22 m short. Its time covers filtering, setInputTarget and align, i.e.
// everything after loading, like our time_ms.total.
//
// Per set of pairs and configuration: a round's time is the mean of
// time_ms.total over the set's pairs; the table gives the median and min-max
// of that over rounds, the mean iterations, final score (Eq. 10 on the last
// layer; not comparable with PCL's), translation and rotation error and the
// success rate over all runs, and the median over rounds of the per-round
// ratio PCL time / ours.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "lab/eval/nees.h"
#include "lab/eval/statistics.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/registration/registration.h"
#include "tools/common/bench_configurations.h"
#include "tools/common/bench_pairs.h"
#include "tools/common/bench_plot.h"
#include "tools/common/bench_report.h"
#include "tools/common/gnuplot.h"
#include "tools/common/list_flags.h"
#include "tools/common/matrix_text.h"
#include "tools/common/output_files.h"
#include "tools/common/tool_main.h"

#ifdef MLNDT_WITH_PCL
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/ndt.h>
#endif

// clang-format off
DEFINE_string(pairs, "koide3,kitti",
              "Comma-separated bundled sets of pairs: koide3, kitti (when --data_dir has no "
              "reference_pairs.json)");
DEFINE_string(data_dir, MLNDT_DATA_DIR,
              "A data set folder with reference_pairs.json (scans in it or its pcd/), or a "
              "folder with koide3/ and kitti/ (the repository's data/)");
DEFINE_string(starts, "identity", "Comma-separated starts: identity, prior, offsets");
DEFINE_string(offsets, "x:0.5,2;yaw:10,30",
              "--starts=offsets: ';'-separated families AXES:values of the reference pushed "
              "off (x, y, z [m], roll, pitch, yaw [deg]; mlndt_suite's syntax)");
DEFINE_int32(max_pairs, 0, "At most this many pairs per folder, smallest steps first; 0: all");
DEFINE_string(minimizers, "trust_region",
              "Comma-separated Ceres minimizers (ceres backend only): trust_region, bfgs, lbfgs "
              "(line search)");
DEFINE_string(jacobians, "autodiff",
              "Comma-separated Ceres Jacobians (ceres backend only): autodiff, analytic");
DEFINE_string(losses, "cauchy", "Comma-separated robust losses: none, huber, cauchy");
DEFINE_string(loss_scales, "1.5", "Comma-separated loss scales (Mahalanobis distance)");
DEFINE_string(output_plot, "",
              "Write a PNG of time against error per configuration (Pareto front marked), with "
              "FILE.dat and FILE.gp beside it");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program for --output_plot");
DEFINE_string(kitti_gaps, "1", "Comma-separated frame gaps of the kitti pairs: i+gap onto i");
DEFINE_string(defaults, "current",
              "Comma-separated defaults the configurations start from: current "
              "(RegistrationOptions()), previous (2 m finest cells, POINTS coarse weighting, "
              "Cauchy scale 3, step tolerance 1e-4: the defaults before the reach and precision "
              "change)");
DEFINE_string(backends, "ceres,newton,lm", "Comma-separated backends: ceres, newton, lm");
DEFINE_string(samplings, "gbs",
              "Comma-separated input sampling methods: gbs, random, all, voxel_centroid");
DEFINE_string(gbs_cell_sizes, "1",
              "Comma-separated GBS cell edges [m] (gbs sampling only; the paper's 1 m is the "
              "default)");
DEFINE_string(start_layers, std::to_string(mlndt::LayerScheduleOptions().start_layer),
              "Comma-separated 1-based start layers; <= 0 counts from the finest (0 = last layer)");
DEFINE_string(linear_solvers, "dense_normal_cholesky",
              "Comma-separated Ceres linear solvers (ceres backend only): dense_normal_cholesky, "
              "dense_qr, ...");
DEFINE_string(trust_regions, "levenberg_marquardt",
              "Comma-separated Ceres trust-region strategies (ceres backend only): "
              "levenberg_marquardt, dogleg");
DEFINE_string(threads, "1", "Comma-separated thread counts (Ceres evaluator or OpenMP threads)");
DEFINE_int32(repetitions, 5, "Repetition rounds; timings are the median over rounds");
DEFINE_bool(warmup, true, "Run every configuration once on the first pair, untimed, first");
DEFINE_bool(compare_pcl, false,
            "Also run pcl::NormalDistributionsTransform (needs -DMLNDT_WITH_PCL=ON)");
DEFINE_double(pcl_leaf_size, 0.1, "--compare_pcl: VoxelGrid leaf size for both clouds [m]");
DEFINE_double(pcl_resolution, 1.0, "--compare_pcl: NDT cell size [m]");
DEFINE_double(pcl_step_size, 1.0,
              "--compare_pcl: More-Thuente maximum step length (PCL's default: 0.1)");
DEFINE_double(pcl_transformation_epsilon, 1e-4,
              "--compare_pcl: PCL stops when the squared translation of a step is <= this [m^2]; "
              "1e-4 is a 0.01 m step (see the file comment)");
DEFINE_int32(pcl_max_iterations, 35, "--compare_pcl: iteration cap");
DEFINE_uint64(seed, 1, "Sampling seed (random sampling)");
DEFINE_double(max_translation_error, 0.2, "Success threshold [m]");
DEFINE_double(max_rotation_error, 1.0, "Success threshold [deg]");
DEFINE_string(output_csv, "", "Write one row per set of pairs and configuration to this CSV file");
// clang-format on

namespace mlndt {
namespace {

using tools::BenchFormat;
using tools::BenchRowStats;
using tools::BenchRun;
using tools::ScanPair;

int Fail(const std::string& message) {
  std::cerr << "mlndt_bench: " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << "mlndt_bench: " << message << std::endl;
  return tools::kExitUsage;
}

BenchRun Evaluate(const Isometry3d& truth,
                  const Isometry3d& estimate,
                  bool usable) {
  BenchRun r;
  r.translation_error_m = TranslationErrorM(truth, estimate);
  r.rotation_error_deg = RotationErrorRad(truth, estimate) * kRadToDeg;
  r.success = usable && r.translation_error_m < FLAGS_max_translation_error &&
              r.rotation_error_deg < FLAGS_max_rotation_error;
  return r;
}

BenchRun RunMlndt(const RegistrationOptions& options, const ScanPair& pair) {
  RegistrationSummary summary;
  Register(options,
           *pair.reference,
           *pair.input,
           pair.initial_reference_from_input,
           &summary);
  BenchRun r = Evaluate(pair.reference_from_input_truth,
                        summary.reference_from_input,
                        summary.IsSolutionUsable());
  if (summary.IsSolutionUsable() && summary.covariance.allFinite() &&
      summary.covariance.trace() > 0.0) {
    const Vector6d e = IsometryToPoseVector(summary.reference_from_input) -
                       IsometryToPoseVector(pair.reference_from_input_truth);
    r.nees = Nees(e, summary.covariance);
  }
  r.time_ms = summary.total_time_s * 1e3;
  r.iterations = summary.num_iterations;
  r.score = summary.final_score;
  r.converged = summary.termination_type == TerminationType::CONVERGENCE;
  return r;
}

#ifdef MLNDT_WITH_PCL
using PclCloud = pcl::PointCloud<pcl::PointXYZ>;

// Converting is part of loading, so it is done once, outside the timing.
PclCloud::Ptr ToPcl(const PointCloud& cloud) {
  PclCloud::Ptr out(new PclCloud);
  out->reserve(cloud.size());
  for (const Eigen::Vector3d& p : cloud.points()) {
    out->push_back(pcl::PointXYZ(static_cast<float>(p.x()),
                                 static_cast<float>(p.y()),
                                 static_cast<float>(p.z())));
  }
  return out;
}

struct PclPair {
  PclCloud::Ptr reference;
  PclCloud::Ptr input;
};

// PCL NDT as the --pcl_* flags say (see the file comment).
tools::BenchRun RunPclNdt(const PclPair& pair, const Isometry3d& truth) {
  const double start = NowSeconds();
  pcl::VoxelGrid<pcl::PointXYZ> voxel_grid;
  const float leaf = static_cast<float>(FLAGS_pcl_leaf_size);
  voxel_grid.setLeafSize(leaf, leaf, leaf);
  PclCloud::Ptr reference(new PclCloud), input(new PclCloud);
  voxel_grid.setInputCloud(pair.reference);
  voxel_grid.filter(*reference);
  voxel_grid.setInputCloud(pair.input);
  voxel_grid.filter(*input);
  pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ> ndt;
  ndt.setTransformationEpsilon(FLAGS_pcl_transformation_epsilon);
  ndt.setStepSize(FLAGS_pcl_step_size);
  ndt.setResolution(static_cast<float>(FLAGS_pcl_resolution));
  ndt.setMaximumIterations(FLAGS_pcl_max_iterations);
  ndt.setInputTarget(reference);
  ndt.setInputSource(input);
  PclCloud aligned;
  const double align_start = NowSeconds();
  ndt.align(aligned, Eigen::Matrix4f::Identity());
  const double end = NowSeconds();

  Isometry3d estimate = Isometry3d::Identity();
  estimate.matrix() = ndt.getFinalTransformation().cast<double>();
  // Re-orthonormalise the single-precision rotation.
  estimate.linear() =
      Eigen::Quaterniond(estimate.linear()).normalized().toRotationMatrix();
  tools::BenchRun r = Evaluate(truth, estimate, ndt.hasConverged());
  r.time_ms = (end - start) * 1e3;
  r.align_ms = (end - align_start) * 1e3;
  r.iterations = ndt.getFinalNumIteration();
  // PCL also reports convergence when it stops at the iteration cap.
  r.converged = ndt.hasConverged() && r.iterations < ndt.getMaximumIterations();
  return r;
}
#endif

// Runs every method on every pair; results[method][round][pair]. Each round
// alternates the methods pair by pair and rotates their order from round to
// round, so that machine noise hits all methods alike.
template <typename RunMethod>
std::vector<std::vector<std::vector<BenchRun>>> RunRounds(
    size_t num_methods, size_t num_pairs, const RunMethod& run_method) {
  if (FLAGS_warmup) {
    for (size_t m = 0; m < num_methods; ++m) run_method(m, 0);
  }
  const size_t rounds = static_cast<size_t>(FLAGS_repetitions);
  std::vector<std::vector<std::vector<BenchRun>>> results(
      num_methods,
      std::vector<std::vector<BenchRun>>(rounds,
                                         std::vector<BenchRun>(num_pairs)));
  const double bench_start = NowSeconds();
  for (size_t round = 0; round < rounds; ++round) {
    for (size_t p = 0; p < num_pairs; ++p) {
      for (size_t k = 0; k < num_methods; ++k) {
        const size_t method = (k + round) % num_methods;  // Rotated order.
        results[method][round][p] = run_method(method, p);
      }
    }
    std::cerr << "mlndt_bench: round " << round + 1 << "/" << FLAGS_repetitions
              << " done after "
              << BenchFormat("%.1f", NowSeconds() - bench_start) << " s"
              << std::endl;
  }
  return results;
}

void PrintPreamble(const std::vector<std::string>& sets,
                   const std::vector<ScanPair>& pairs,
                   size_t num_configurations,
                   bool with_pcl) {
  std::cout << "mlndt_bench: " << FLAGS_repetitions << " round(s); "
            << num_configurations << " configuration(s)"
            << (with_pcl ? " + pcl::NDT" : "")
            << "; time = per round, mean time_ms.total over the set's pairs: "
               "median and min-max "
               "over rounds\n";
  for (const std::string& set : sets) {
    size_t count = 0;
    for (const ScanPair& pair : pairs) count += pair.set == set;
    std::cout << "  " << set << ": " << count << " run(s) a round"
              << (set == "kitti" ? " (gaps " + FLAGS_kitti_gaps + ")" : "")
              << "\n";
  }
  std::cout << "\n";
}

void PrintNotes(bool with_pcl, const std::vector<std::string>& notes) {
  std::cout << "\n- success: translation error < "
            << FLAGS_max_translation_error << " m and rotation error < "
            << FLAGS_max_rotation_error << " deg\n"
            << "- converged: stopped on the convergence test, not on the "
               "iteration cap\n"
            << "- iters, score, err_t, err_r: means over runs; score is Eq. "
               "(10) on the last "
               "layer (mlndt only)\n"
            << "- nees: e^T P^-1 e of the usable runs against the reference, "
               "P = the registration covariance (6 if consistent)\n";
  if (with_pcl) {
    std::cout << "- pcl/ours: median over rounds of the per-round time ratio; "
                 "pcl_ndt is "
                 "single-threaded\n";
  }
  for (const std::string& note : notes) std::cout << "- " << note << "\n";
}

// The table (and CSV rows) per set of pairs and method; PCL's row last.
int Report(const std::vector<std::string>& sets,
           const std::vector<ScanPair>& pairs,
           const std::vector<tools::BenchConfiguration>& configurations,
           bool with_pcl,
           const std::vector<std::vector<std::vector<BenchRun>>>& results,
           std::ostringstream* csv) {  // nullptr: no --output_csv.
  PrintPreamble(sets, pairs, configurations.size(), with_pcl);
  std::vector<std::vector<std::string>> table = {tools::BenchTableHeader()};
  if (csv != nullptr) *csv << tools::BenchCsvHeader();
  std::vector<std::string> notes;
  std::vector<tools::BenchPlotPoint> plot;
  for (const std::string& set : sets) {
    std::vector<size_t> indices;
    for (size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p].set == set) indices.push_back(p);
    }
    std::vector<BenchRowStats> stats;
    for (const auto& method_results : results)
      stats.push_back(tools::SummariseRuns(method_results, indices));
    const BenchRowStats* pcl = with_pcl ? &stats.back() : nullptr;
    for (size_t m = 0; m < stats.size(); ++m) {
      const bool is_pcl = m == configurations.size();
      const tools::BenchMethodLabels labels =
          is_pcl ? tools::PclLabels(FLAGS_pcl_leaf_size)
                 : tools::ConfigurationLabels(configurations[m]);
      table.push_back(tools::BenchTableRow(set, labels, stats[m], pcl));
      plot.push_back({set,
                      tools::ShortLabel(labels),
                      ComputeStats(stats[m].round_times_ms).median,
                      stats[m].mean_translation_error_m});
      if (csv != nullptr)
        *csv << tools::BenchCsvRow(set, labels, stats[m], pcl) << "\n";
      if (is_pcl) {
        notes.push_back(
            set +
            ": pcl_ndt align() alone (without filtering and setInputTarget): "
            "median " +
            BenchFormat("%.1f", ComputeStats(stats[m].round_align_ms).median) +
            " ms");
      }
    }
  }
  tools::PrintMarkdownTable(table);
  PrintNotes(with_pcl, notes);
  std::string error;
  if (csv != nullptr &&
      !WriteFileAtomically(FLAGS_output_csv, csv->str(), &error)) {
    return Fail(error);
  }
  if (!FLAGS_output_plot.empty() &&
      !tools::WriteBenchPlot(FLAGS_gnuplot, FLAGS_output_plot, plot, &error)) {
    return Fail(error);
  }
  return tools::kExitOk;
}

int Run() {
  if (FLAGS_repetitions < 1) return Refuse("--repetitions must be >= 1");
#ifndef MLNDT_WITH_PCL
  if (FLAGS_compare_pcl) {
    return Refuse(
        "--compare_pcl: this build has no PCL; configure with "
        "-DMLNDT_WITH_PCL=ON");
  }
#endif
  std::string error;
  const tools::BenchGridFlags grid{FLAGS_defaults,
                                   FLAGS_backends,
                                   FLAGS_samplings,
                                   FLAGS_gbs_cell_sizes,
                                   FLAGS_start_layers,
                                   FLAGS_linear_solvers,
                                   FLAGS_trust_regions,
                                   FLAGS_minimizers,
                                   FLAGS_jacobians,
                                   FLAGS_losses,
                                   FLAGS_loss_scales,
                                   FLAGS_threads,
                                   FLAGS_seed};
  std::vector<tools::BenchConfiguration> configurations;
  if (!tools::ParseBenchConfigurations(grid, &configurations, &error))
    return Refuse(error);
  if (!tools::CheckOutputFile("output_csv", FLAGS_output_csv, &error) ||
      !tools::CheckOutputFile("output_plot", FLAGS_output_plot, &error)) {
    return Refuse(error);
  }
  if (!FLAGS_output_plot.empty() && !tools::GnuplotAvailable(FLAGS_gnuplot)) {
    return Refuse("--output_plot: '" + FLAGS_gnuplot +
                  "' does not run (install gnuplot or pass --gnuplot)");
  }
  tools::BenchPairsOptions pair_options;
  pair_options.data_dir = FLAGS_data_dir;
  pair_options.sets = FLAGS_pairs;
  pair_options.kitti_gaps = FLAGS_kitti_gaps;
  pair_options.starts = FLAGS_starts;
  pair_options.offsets = FLAGS_offsets;
  pair_options.max_pairs = FLAGS_max_pairs;
  std::vector<ScanPair> pairs;
  if (!tools::LoadBenchPairs(pair_options, &pairs, &error)) {
    return Refuse(error);
  }
  const std::vector<std::string> sets = tools::BenchSets(pairs);
  std::ostringstream csv;

  // Methods: the configurations, then PCL (when compared).
  const size_t num_configurations = configurations.size();
  const bool with_pcl = FLAGS_compare_pcl;
  std::vector<RegistrationOptions> options;
  for (const auto& c : configurations) options.push_back(c.Options(FLAGS_seed));
#ifdef MLNDT_WITH_PCL
  std::vector<PclPair> pcl_pairs;
  if (with_pcl) {
    for (const ScanPair& pair : pairs) {
      pcl_pairs.push_back({ToPcl(*pair.reference), ToPcl(*pair.input)});
    }
  }
#endif
  auto run_method = [&](size_t method, size_t p) {
#ifdef MLNDT_WITH_PCL
    if (method == num_configurations) {
      return RunPclNdt(pcl_pairs[p], pairs[p].reference_from_input_truth);
    }
#endif
    return RunMlndt(options[method], pairs[p]);
  };
  const auto results = RunRounds(
      num_configurations + (with_pcl ? 1 : 0), pairs.size(), run_method);
  return Report(sets,
                pairs,
                configurations,
                with_pcl,
                results,
                FLAGS_output_csv.empty() ? nullptr : &csv);
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Benchmarks registration configurations on real pairs with ground "
          "truth.\n"
          "  mlndt_bench [--pairs=koide3,kitti] [--backends=ceres,newton,lm] "
          "[--repetitions=5] [--compare_pcl] [--output_csv=FILE]",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
