#include "lab/bench/bench_option_tables.h"

#include "lab/bench/bench.h"

namespace mlndt {

const OptionTable& PclBenchOptionsTable() {
  using S = PclBenchOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("PclBenchOptions")
          .Double("leaf_size_m",
                  &S::leaf_size_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "PCL NDT: VoxelGrid leaf size for both clouds.")
          .Double("ndt_resolution_m",
                  &S::ndt_resolution_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "PCL NDT: cell size.")
          .Double("ndt_step_size_m",
                  &S::ndt_step_size_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "PCL NDT: More-Thuente maximum step length (PCL's "
                  "default: 0.1).")
          .Double("ndt_transformation_epsilon",
                  &S::ndt_transformation_epsilon,
                  "m^2",
                  Closed(0.0, 1e9),
                  "PCL NDT stops when the squared translation of a step is "
                  "<= this; 1e-4 is a 0.01 m step (lab/bench/pcl_methods.h).")
          .Int("ndt_max_iterations",
               &S::ndt_max_iterations,
               AtLeast(1),
               "PCL NDT: iteration cap.")
          .Double("gicp_leaf_size_m",
                  &S::gicp_leaf_size_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "PCL GICP: VoxelGrid leaf size for both clouds.")
          .Double("gicp_max_correspondence_distance_m",
                  &S::gicp_max_correspondence_distance_m,
                  "m",
                  LeftOpen(0.0, 1e9),
                  "PCL GICP: correspondences farther than this are ignored.")
          .Int("gicp_max_iterations",
               &S::gicp_max_iterations,
               AtLeast(1),
               "PCL GICP: iteration cap.")
          .Build();
  return table;
}

const OptionTable& BenchThresholdsTable() {
  using S = BenchThresholds;
  static const OptionTable table =
      OptionTableBuilder<S>("BenchThresholds")
          .Double("max_translation_error_m",
                  &S::max_translation_error_m,
                  "m",
                  AtLeast(0.0),
                  "A run succeeds within this translation error...")
          .Double("max_rotation_error_deg",
                  &S::max_rotation_error_deg,
                  "deg",
                  AtLeast(0.0),
                  "... and this rotation error.")
          .Build();
  return table;
}

const OptionTable& BenchRoundsOptionsTable() {
  using S = BenchRoundsOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("BenchRoundsOptions")
          .Int("repetitions",
               &S::repetitions,
               AtLeast(1),
               "Repetition rounds; timings are the median over rounds.")
          .Bool("warmup",
                &S::warmup,
                "Run every method once on the first pair, untimed, first.")
          .Struct("thresholds",
                  &S::thresholds,
                  BenchThresholdsTable(),
                  "The success thresholds.")
          .Build();
  return table;
}

const OptionTable& BenchPairsOptionsTable() {
  using S = BenchPairsOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("BenchPairsOptions")
          .Int("max_pairs",
               &S::max_pairs,
               AtLeast(0),
               "At most this many pairs per folder, smallest steps first; "
               "0 = all.")
          .Build();
  return table;
}

const OptionTable& BenchOptionsTable() {
  using S = BenchOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("BenchOptions")
          .Struct("pairs",
                  &S::pairs,
                  BenchPairsOptionsTable(),
                  "The pairs (single values; the lists are flags of their "
                  "own).")
          .Struct("rounds", &S::rounds, BenchRoundsOptionsTable(), "Rounds.")
          .Bool("compare_pcl_ndt",
                &S::compare_pcl_ndt,
                "Also run pcl::NormalDistributionsTransform (needs "
                "-DMLNDT_WITH_PCL=ON).")
          .Bool("compare_pcl_gicp",
                &S::compare_pcl_gicp,
                "Also run pcl::GeneralizedIterativeClosestPoint (needs "
                "-DMLNDT_WITH_PCL=ON).")
          .Bool("one_shot",
                &S::one_shot,
                "Also time every pair one-shot (a child process per "
                "registration), as the sets '<set> one-shot'; the others "
                "are warm (in this process).")
          .Struct("pcl",
                  &S::pcl,
                  PclBenchOptionsTable(),
                  "The PCL peers' settings.")
          .Build();
  return table;
}

}  // namespace mlndt
