// mlndt_bench: times registration methods on real scan pairs with
// references and reports speed and accuracy per method, all methods in one
// run, alternating (lab/bench/bench_rounds.h).
//
//   mlndt_bench [--data_dir=FOLDER | --pairs=koide3,kitti]
//               [--starts=identity,prior,offsets] [--backends=ceres,newton,lm]
//               [--defaults=current,previous] [--repetitions=5]
//               [--compare_pcl_ndt] [--compare_pcl_gicp]
//               [--output_csv=FILE] [--output_plot=FILE.png]
//
// Pairs: lab/bench/bench_pairs.h. Methods: the grid of configurations of
// the list flags (lab/bench/bench_configurations.h), then PCL's NDT and
// GICP (lab/bench/pcl_methods.h; build with -DMLNDT_WITH_PCL=ON). Rows:
// lab/bench/bench_report.h; docs/performance.md shows runs.
//
// Per set of pairs and method: a round's time is the mean of time_ms.total
// over the set's pairs; the table gives the median and min-max of that over
// rounds, the mean iterations, final score (Eq. 10 on the last layer; not
// comparable with PCL's), translation and rotation error, NEES and the
// success rate over all runs, and the median over rounds of the per-round
// ratio PCL NDT time / ours. Exit 0 with the table, 2 on a refused flag or
// input, 1 when an output file cannot be written.

#include <gflags/gflags.h>

#include <iostream>
#include <string>
#include <vector>

#include "lab/bench/bench.h"
#include "lab/bench/bench_plot.h"
#include "lab/bench/bench_report.h"
#include "lab/report/gnuplot.h"
#include "mlndt/common/atomic_file.h"
#include "tools/cli/bench_flags.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/output_files.h"
#include "tools/cli/tool_main.h"

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
DEFINE_string(minimizers, "trust_region",
              "Comma-separated Ceres minimizers (ceres backend only): trust_region, bfgs, lbfgs "
              "(line search)");
DEFINE_string(jacobians, "autodiff",
              "Comma-separated Ceres Jacobians (ceres backend only): autodiff, analytic");
DEFINE_string(losses, "cauchy", "Comma-separated robust losses: none, huber, cauchy");
DEFINE_string(loss_scales, "", "Comma-separated loss scales (Mahalanobis distance); empty: each "
              "--defaults' own (current 1.5, previous 3)");
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
DEFINE_uint64(seed, 1, "Sampling seed (random sampling)");
DEFINE_string(output_csv, "", "Write one row per set of pairs and configuration to this CSV file");
// clang-format on

namespace mlndt {
namespace {

// A list flag parsed by `parse` (tools/cli/list_flags.h); an empty list
// when it does not parse (the lab then names the flag and what it expects).
template <typename T>
std::vector<T> List(const std::string& text,
                    bool (*parse)(const std::string&, std::vector<T>*)) {
  std::vector<T> values;
  if (!parse(text, &values)) values.clear();
  return values;
}

constexpr auto Items = tools::SplitList;
constexpr auto Ints = tools::ParseIntList;
constexpr auto Numbers = tools::ParseNumberList;

BenchGrid GridFromFlags() {
  BenchGrid grid;
  grid.defaults = List(FLAGS_defaults, Items);
  grid.backends = List(FLAGS_backends, Items);
  grid.samplings = List(FLAGS_samplings, Items);
  grid.gbs_cell_sizes = List(FLAGS_gbs_cell_sizes, Numbers);
  grid.start_layers = List(FLAGS_start_layers, Ints);
  grid.linear_solvers = List(FLAGS_linear_solvers, Items);
  grid.trust_regions = List(FLAGS_trust_regions, Items);
  grid.minimizers = List(FLAGS_minimizers, Items);
  grid.jacobians = List(FLAGS_jacobians, Items);
  grid.losses = List(FLAGS_losses, Items);
  grid.threads = List(FLAGS_threads, Ints);
  grid.seed = FLAGS_seed;
  return grid;
}

// The options from the flags; false with *error naming a flag out of range.
bool OptionsFromFlags(BenchOptions* options, std::string* error) {
  options->grid = GridFromFlags();
  if (!Numbers(FLAGS_loss_scales, &options->grid.loss_scales)) {
    *error = "--loss_scales=" + FLAGS_loss_scales +
             ": expected comma-separated numbers (or none: each --defaults' "
             "own scale)";
    return false;
  }
  options->pairs.data_dir = FLAGS_data_dir;
  options->pairs.sets = List(FLAGS_pairs, Items);
  options->pairs.kitti_gaps = List(FLAGS_kitti_gaps, Ints);
  options->pairs.starts = List(FLAGS_starts, Items);
  options->pairs.offsets = FLAGS_offsets;
  if (!tools::BenchFlags().Apply(options, error)) return false;
  const int repetitions = options->rounds.repetitions;
  options->rounds.on_round = [repetitions](int round, double seconds) {
    std::cerr << "mlndt_bench: round " << round << "/" << repetitions
              << " done after " << BenchFormat("%.1f", seconds) << " s"
              << std::endl;
  };
  return true;
}

// The output files can be written and gnuplot runs, before any work.
bool CheckOutputs(std::string* error) {
  if (!tools::CheckOutputFile("output_csv", FLAGS_output_csv, error) ||
      !tools::CheckOutputFile("output_plot", FLAGS_output_plot, error)) {
    return false;
  }
  if (!FLAGS_output_plot.empty() && !GnuplotAvailable(FLAGS_gnuplot)) {
    *error = "--output_plot: '" + FLAGS_gnuplot +
             "' does not run (install gnuplot or pass --gnuplot)";
    return false;
  }
  return true;
}

int Run() {
  BenchOptions options;
  BenchResult result;
  std::string error;
  if (!OptionsFromFlags(&options, &error) || !CheckOutputs(&error) ||
      !RunBench(options, &result, &error)) {
    std::cerr << "mlndt_bench: " << error << std::endl;
    return tools::kExitUsage;
  }
  std::cout << BenchReportText(options, result);
  const bool written =
      (FLAGS_output_csv.empty() ||
       WriteFileAtomically(FLAGS_output_csv, BenchCsvText(result), &error)) &&
      (FLAGS_output_plot.empty() ||
       WriteBenchPlot(
           FLAGS_gnuplot, FLAGS_output_plot, BenchPlotPoints(result), &error));
  if (!written) {
    std::cerr << "mlndt_bench: " << error << std::endl;
    return tools::kExitFailed;
  }
  return tools::kExitOk;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Benchmarks registration configurations and PCL's NDT and GICP on "
          "real pairs with references.\n"
          "  mlndt_bench [--pairs=koide3,kitti | --data_dir=FOLDER] "
          "[--backends=ceres,newton,lm] [--repetitions=5] [--compare_pcl_ndt] "
          "[--compare_pcl_gicp] [--output_csv=FILE]",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
