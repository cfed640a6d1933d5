#pragma once

// mlndt_bench's round robin: every method on every pair, `repetitions`
// rounds. Each round alternates the methods pair by pair and rotates their
// order from round to round (round r starts with method r mod M), so that
// machine noise hits all methods alike. The one-shot pairs
// (ScanPair::one_shot) run first, each registration in a child process
// (bench_child.h); then the warm-up and the other pairs, in this process.

#include <functional>
#include <memory>
#include <vector>

#include "lab/bench/bench_method.h"

namespace mlndt {

struct BenchRoundsOptions {
  int repetitions = 5;  // >= 1.
  // Run every method once on the first pair, untimed, first.
  bool warmup = true;
  BenchThresholds thresholds;
  // Called after each round with its 1-based number and the seconds since
  // the first round started (progress); may be empty.
  std::function<void(int round, double seconds)> on_round;
};

// The order in which round `round` runs `num_methods` methods on each pair.
std::vector<size_t> RoundOrder(size_t num_methods, size_t round);

// results[method][round][pair]: each method's estimates scored against the
// pairs' references. The methods must have been prepared.
std::vector<std::vector<std::vector<BenchRun>>> RunBenchRounds(
    const BenchRoundsOptions& options,
    const std::vector<std::unique_ptr<BenchMethod>>& methods,
    const std::vector<ScanPair>& pairs);

}  // namespace mlndt
