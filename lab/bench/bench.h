#pragma once

// mlndt_bench's one call: loads the pairs (lab/bench/bench_pairs.h), makes
// the methods (the configurations of lab/bench/bench_configurations.h, then
// the PCL peers asked for, lab/bench/pcl_methods.h), runs the rounds
// (lab/bench/bench_rounds.h) and summarises each (set of pairs, method)
// (lab/bench/bench_stats.h). lab/bench/bench_report.h writes the result.

#include <string>
#include <vector>

#include "lab/bench/bench_configurations.h"
#include "lab/bench/bench_method.h"
#include "lab/bench/bench_pairs.h"
#include "lab/bench/bench_rounds.h"
#include "lab/bench/bench_stats.h"
#include "lab/bench/pcl_bench_options.h"

namespace mlndt {

struct BenchOptions {
  BenchGrid grid;
  BenchPairsOptions pairs;
  BenchRoundsOptions rounds;
  // The PCL peers (need the build with PCL), after the configurations.
  bool compare_pcl_ndt = false;
  bool compare_pcl_gicp = false;
  PclBenchOptions pcl;
  // Also time every pair one-shot, each registration in a child process
  // (lab/bench/bench_child.h), in sets named "<set> one-shot"; the other
  // sets are warm (every method registers in this process, round after
  // round).
  bool one_shot = true;
};

struct BenchResult {
  size_t num_configurations = 0;
  std::vector<BenchMethodLabels> methods;  // Configurations, then peers.
  // The groups of pairs (BenchSets) and how many runs each has a round.
  std::vector<std::string> sets;
  std::vector<size_t> set_pairs;
  std::vector<std::vector<BenchRowStats>> stats;  // [set][method]
};

// Refuses bad options before any registration (false with *error naming
// the flag: a bad grid item, a PCL peer without PCL, no pair to load);
// otherwise runs everything and fills *result.
bool RunBench(const BenchOptions& options,
              BenchResult* result,
              std::string* error);

}  // namespace mlndt
