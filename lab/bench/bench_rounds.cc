#include "lab/bench/bench_rounds.h"

#include "mlndt/common/timer.h"

namespace mlndt {

std::vector<size_t> RoundOrder(size_t num_methods, size_t round) {
  std::vector<size_t> order;
  for (size_t k = 0; k < num_methods; ++k) {
    order.push_back((k + round) % num_methods);
  }
  return order;
}

std::vector<std::vector<std::vector<BenchRun>>> RunBenchRounds(
    const BenchRoundsOptions& options,
    const std::vector<std::unique_ptr<BenchMethod>>& methods,
    const std::vector<ScanPair>& pairs) {
  auto run = [&](size_t method, size_t p) {
    return ScoreEstimate(methods[method]->Run(p, pairs[p]),
                         pairs[p].reference_from_input_truth,
                         options.thresholds);
  };
  if (options.warmup && !pairs.empty()) {
    for (size_t m = 0; m < methods.size(); ++m) run(m, 0);
  }
  const size_t rounds = static_cast<size_t>(options.repetitions);
  std::vector<std::vector<std::vector<BenchRun>>> results(
      methods.size(),
      std::vector<std::vector<BenchRun>>(rounds,
                                         std::vector<BenchRun>(pairs.size())));
  const double start = NowSeconds();
  for (size_t round = 0; round < rounds; ++round) {
    const std::vector<size_t> order = RoundOrder(methods.size(), round);
    for (size_t p = 0; p < pairs.size(); ++p) {
      for (const size_t method : order) {
        results[method][round][p] = run(method, p);
      }
    }
    if (options.on_round) {
      options.on_round(static_cast<int>(round) + 1, NowSeconds() - start);
    }
  }
  return results;
}

}  // namespace mlndt
