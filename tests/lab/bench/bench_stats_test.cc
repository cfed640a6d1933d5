#include "lab/bench/bench_stats.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mlndt {
namespace {

BenchRun MakeRun(double time_ms,
                 double err_t,
                 bool success,
                 double nees = NAN) {
  BenchRun r;
  r.time_ms = time_ms;
  r.translation_error_m = err_t;
  r.rotation_error_deg = 10.0 * err_t;
  r.iterations = static_cast<int>(time_ms);
  r.point_iterations = 100 * static_cast<int64_t>(time_ms);
  r.score = 2.0 * time_ms;
  r.success = success;
  r.converged = true;
  r.nees = nees;
  return r;
}

// Two rounds of three pairs; the row takes pairs 0 and 2.
TEST(SummariseRuns, MeansPerRoundAndOverRunsOfTheChosenPairs) {
  const std::vector<std::vector<BenchRun>> results = {
      {MakeRun(10, 0.1, true, 4.0),
       MakeRun(1000, 9.0, false),
       MakeRun(30, 0.3, false)},
      {MakeRun(20, 0.2, true, 8.0),
       MakeRun(1000, 9.0, false),
       MakeRun(60, 0.6, true)}};
  const BenchRowStats s = SummariseRuns(results, {0, 2});
  ASSERT_EQ(s.round_times_ms.size(), 2u);
  EXPECT_DOUBLE_EQ(s.round_times_ms[0], 20.0);  // (10 + 30) / 2.
  EXPECT_DOUBLE_EQ(s.round_times_ms[1], 40.0);  // (20 + 60) / 2.
  EXPECT_EQ(s.runs, 4);
  EXPECT_EQ(s.successes, 3);
  EXPECT_EQ(s.converged, 4);
  EXPECT_DOUBLE_EQ(s.mean_iterations, 30.0);
  EXPECT_DOUBLE_EQ(s.mean_point_iterations, 3000.0);
  EXPECT_DOUBLE_EQ(s.mean_score, 60.0);
  EXPECT_DOUBLE_EQ(s.mean_translation_error_m, 0.3);
  EXPECT_DOUBLE_EQ(s.max_translation_error_m, 0.6);
  EXPECT_DOUBLE_EQ(s.mean_rotation_error_deg, 3.0);
  EXPECT_DOUBLE_EQ(s.max_rotation_error_deg, 6.0);
  // NEES over the runs that have one (4 and 8).
  EXPECT_DOUBLE_EQ(s.nees_mean, 6.0);
  EXPECT_DOUBLE_EQ(s.nees_median, 6.0);
}

// PCL's runs count no point iterations (-1): the mean skips them, and is
// NaN when no run counts them.
TEST(SummariseRuns, PointIterationsOverTheRunsThatCountThem) {
  BenchRun uncounted = MakeRun(10, 0.1, true);
  uncounted.point_iterations = -1;
  EXPECT_TRUE(
      std::isnan(SummariseRuns({{uncounted}}, {0}).mean_point_iterations));
  const BenchRowStats s =
      SummariseRuns({{uncounted, MakeRun(20, 0.1, true)}}, {0, 1});
  EXPECT_DOUBLE_EQ(s.mean_point_iterations, 2000.0);
}

TEST(SummariseRuns, NoNeesWithoutCovariances) {
  const BenchRowStats s = SummariseRuns({{MakeRun(5, 0.1, true)}}, {0});
  EXPECT_TRUE(std::isnan(s.nees_mean));
  EXPECT_TRUE(std::isnan(s.nees_median));
}

// Median, min, max of the round times; the ratio is the median of the
// per-round ratios, not the ratio of the medians.
TEST(RowTimes, MedianMinMaxAndMedianOfPerRoundRatios) {
  BenchRowStats ours, reference;
  ours.round_times_ms = {10.0, 40.0, 20.0};
  reference.round_times_ms = {100.0, 120.0, 300.0};  // Ratios 10, 3, 15.
  const BenchRowTimes t = RowTimes(ours, &reference);
  EXPECT_DOUBLE_EQ(t.median, 20.0);
  EXPECT_DOUBLE_EQ(t.min, 10.0);
  EXPECT_DOUBLE_EQ(t.max, 40.0);
  EXPECT_DOUBLE_EQ(t.reference_ratio, 10.0);
  EXPECT_NE(t.reference_ratio, 120.0 / 20.0);  // Ratio of the medians.
  EXPECT_TRUE(std::isnan(RowTimes(ours, nullptr).reference_ratio));
}

TEST(RowTimes, EvenNumberOfRoundsTakesTheMeanOfTheMiddleTwo) {
  BenchRowStats s;
  s.round_times_ms = {4.0, 1.0, 3.0, 2.0};
  EXPECT_DOUBLE_EQ(RowTimes(s, nullptr).median, 2.5);
}

}  // namespace
}  // namespace mlndt
