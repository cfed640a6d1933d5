#pragma once

// Summary statistics of a list of numbers: the one definition of mean, std,
// median and percentile the reports and tools use.

#include <cstddef>
#include <vector>

namespace mlndt {

// std is the sample standard deviation (n - 1; 0 for n < 2); median is the
// middle value or the mean of the two middle values; p95 is the nearest-rank
// 95th percentile, the value at sorted index ceil(0.95 n) - 1. All zero for
// an empty list. Non-finite values are not filtered: remove them first.
struct Stats {
  size_t count = 0;
  double mean = 0.0;
  double std = 0.0;
  double min = 0.0;
  double max = 0.0;
  double median = 0.0;
  double p95 = 0.0;
};

// Takes the values by copy (it sorts them).
Stats ComputeStats(std::vector<double> values);

// Root mean square sqrt(sum v^2 / n); 0 for an empty list.
double Rms(const std::vector<double>& values);

}  // namespace mlndt
