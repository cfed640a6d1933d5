#include "lab/eval/statistics.h"

#include <algorithm>
#include <cmath>

namespace mlndt {

Stats ComputeStats(std::vector<double> values) {
  Stats s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / values.size();
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = values.size() > 1 ? std::sqrt(squares / (values.size() - 1)) : 0.0;
  s.min = values.front();
  s.max = values.back();
  const size_t n = values.size();
  s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * n));
  s.p95 = values[std::max<size_t>(rank, 1) - 1];
  return s;
}

double Rms(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double squares = 0.0;
  for (double v : values) squares += v * v;
  return std::sqrt(squares / static_cast<double>(values.size()));
}

}  // namespace mlndt
