#include "lab/bench/bench_rounds.h"

#include <iostream>
#include <limits>
#include <string>

#include "lab/bench/bench_child.h"
#include "mlndt/common/timer.h"

namespace mlndt {

std::vector<size_t> RoundOrder(size_t num_methods, size_t round) {
  std::vector<size_t> order;
  for (size_t k = 0; k < num_methods; ++k) {
    order.push_back((k + round) % num_methods);
  }
  return order;
}

namespace {

// One run of `method` on pairs[p]: in a child process for a one-shot pair.
BenchEstimate RunOnce(BenchMethod& method,
                      size_t p,
                      const std::vector<ScanPair>& pairs) {
  if (!pairs[p].one_shot) return method.Run(p, pairs[p]);
  BenchEstimate estimate;
  std::string error;
  if (!RunInChildProcess(
          [&] { return method.Run(p, pairs[p]); }, &estimate, &error)) {
    std::cerr << "mlndt_bench: " << pairs[p].label << ": " << error
              << std::endl;
    estimate = BenchEstimate();  // Not usable: counts as a failure.
    estimate.time_ms = std::numeric_limits<double>::quiet_NaN();
  }
  return estimate;
}

}  // namespace

std::vector<std::vector<std::vector<BenchRun>>> RunBenchRounds(
    const BenchRoundsOptions& options,
    const std::vector<std::unique_ptr<BenchMethod>>& methods,
    const std::vector<ScanPair>& pairs) {
  auto run = [&](size_t method, size_t p) {
    return ScoreEstimate(RunOnce(*methods[method], p, pairs),
                         pairs[p].reference_from_input_truth,
                         options.thresholds);
  };
  const size_t rounds = static_cast<size_t>(options.repetitions);
  std::vector<std::vector<std::vector<BenchRun>>> results(
      methods.size(),
      std::vector<std::vector<BenchRun>>(rounds,
                                         std::vector<BenchRun>(pairs.size())));
  const double start = NowSeconds();
  // The one-shot pairs first: their children are forked before the parent
  // has run anything (bench_child.h). Then the warm-up and the warm pairs.
  for (const bool one_shot : {true, false}) {
    std::vector<size_t> phase;
    for (size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p].one_shot == one_shot) phase.push_back(p);
    }
    if (phase.empty()) continue;
    if (!one_shot && options.warmup) {
      for (size_t m = 0; m < methods.size(); ++m) run(m, phase[0]);
    }
    for (size_t round = 0; round < rounds; ++round) {
      const std::vector<size_t> order = RoundOrder(methods.size(), round);
      for (const size_t p : phase) {
        for (const size_t method : order) {
          results[method][round][p] = run(method, p);
        }
      }
      if (options.on_round) {
        options.on_round(static_cast<int>(round) + 1, NowSeconds() - start);
      }
    }
  }
  return results;
}

}  // namespace mlndt
