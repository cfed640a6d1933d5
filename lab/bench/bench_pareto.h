#pragma once

// The Pareto front of mlndt_bench's time-vs-error plot: per set of pairs,
// the methods no other method of the set beats in both time and error.

#include <string>
#include <vector>

namespace mlndt {

struct BenchPlotPoint {
  std::string set;
  std::string label;  // ShortLabel (lab/bench/bench_method.h).
  double time_ms = 0.0;
  double error_m = 0.0;
};

// For each point, whether it is on its set's Pareto front: no point of the
// same set has time <= and error <= with one of them strictly smaller.
std::vector<bool> ParetoFront(const std::vector<BenchPlotPoint>& points);

}  // namespace mlndt
