#include "lab/bench/bench_stats.h"

#include <algorithm>
#include <cmath>

#include "lab/eval/statistics.h"

namespace mlndt {
namespace {

double Mean(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  double sum = 0.0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double Median(const std::vector<double>& v) { return ComputeStats(v).median; }

}  // namespace

BenchRowStats SummariseRuns(const std::vector<std::vector<BenchRun>>& results,
                            const std::vector<size_t>& pair_indices) {
  BenchRowStats s;
  std::vector<double> iterations, point_iterations, scores, translation,
      rotation, nees;
  for (const std::vector<BenchRun>& round : results) {
    std::vector<double> times, align;
    for (const size_t p : pair_indices) {
      const BenchRun& r = round[p];
      times.push_back(r.time_ms);
      align.push_back(r.align_ms);
      iterations.push_back(r.iterations);
      if (r.point_iterations >= 0) {
        point_iterations.push_back(static_cast<double>(r.point_iterations));
      }
      scores.push_back(r.score);
      translation.push_back(r.translation_error_m);
      rotation.push_back(r.rotation_error_deg);
      if (std::isfinite(r.nees)) nees.push_back(r.nees);
      ++s.runs;
      s.converged += r.converged;
      s.successes += r.success;
    }
    s.round_times_ms.push_back(Mean(times));
    s.round_align_ms.push_back(Mean(align));
  }
  s.mean_iterations = Mean(iterations);
  s.mean_point_iterations = Mean(point_iterations);
  s.mean_score = Mean(scores);
  s.mean_translation_error_m = Mean(translation);
  s.max_translation_error_m =
      *std::max_element(translation.begin(), translation.end());
  s.mean_rotation_error_deg = Mean(rotation);
  if (!nees.empty()) {
    s.nees_mean = Mean(nees);
    s.nees_median = Median(nees);
  }
  s.max_rotation_error_deg =
      *std::max_element(rotation.begin(), rotation.end());
  return s;
}

BenchRowTimes RowTimes(const BenchRowStats& s, const BenchRowStats* reference) {
  BenchRowTimes t;
  t.median = Median(s.round_times_ms);
  t.min = *std::min_element(s.round_times_ms.begin(), s.round_times_ms.end());
  t.max = *std::max_element(s.round_times_ms.begin(), s.round_times_ms.end());
  if (reference != nullptr) {
    std::vector<double> ratios;
    for (size_t r = 0; r < s.round_times_ms.size(); ++r) {
      ratios.push_back(reference->round_times_ms[r] / s.round_times_ms[r]);
    }
    t.reference_ratio = Median(ratios);
  }
  return t;
}

}  // namespace mlndt
