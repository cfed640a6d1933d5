// ComputeTotals and the error values in report units.

#include "lab/runs/sequence_totals.h"

#include <gtest/gtest.h>

#include <string>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

PairResult Pair(double error_tx_m, bool success, double total_ms) {
  PairResult r;
  r.has_truth = true;
  r.error.components(0) = -error_tx_m;  // Magnitudes are reported.
  r.error.components(5) = -0.01;        // [rad]
  r.error.translation_m = error_tx_m;
  r.error.rotation_rad = 0.01;
  r.success = success;
  r.strict_success = success && error_tx_m < 0.2;
  r.registration.termination_type =
      success ? TerminationType::CONVERGENCE : TerminationType::FAILURE;
  r.guess_check_failed = !success;
  r.times.total_ms = total_ms;
  r.times.map_ms = 1.0;
  r.registration.num_iterations = 10;
  return r;
}

TEST(ErrorValues, AreMagnitudesInCentimetresAndDegrees) {
  const std::vector<double> v = ErrorValues(Pair(0.3, true, 0).error);
  ASSERT_EQ(v.size(), static_cast<size_t>(kNumErrorValues));
  EXPECT_DOUBLE_EQ(v[0], 30.0);
  EXPECT_DOUBLE_EQ(v[5], 0.01 * kRadToDeg);
  EXPECT_DOUBLE_EQ(v[6], 30.0);
  EXPECT_DOUBLE_EQ(v[7], 0.01 * kRadToDeg);
  EXPECT_EQ(std::string(ErrorNames()[0]), "tx_cm");
  EXPECT_EQ(std::string(ErrorNames()[7]), "rotation_deg");
}

TEST(ComputeTotals, CountsRatesAndStatistics) {
  const std::vector<PairResult> results = {
      Pair(0.1, true, 10.0), Pair(0.3, true, 20.0), Pair(2.0, false, 60.0)};
  const SequenceTotals t = ComputeTotals(results);
  EXPECT_EQ(t.pairs, 3u);
  EXPECT_TRUE(t.has_truth);
  EXPECT_EQ(t.successes, 2u);
  EXPECT_EQ(t.strict_successes, 1u);
  EXPECT_EQ(t.registration_failures, 1u);
  EXPECT_EQ(t.guess_check_failures, 1u);
  EXPECT_DOUBLE_EQ(t.success_rate_percent, 200.0 / 3.0);
  EXPECT_DOUBLE_EQ(t.strict_success_rate_percent, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(t.errors[6].mean, 80.0);  // (10 + 30 + 200) / 3 cm.
  EXPECT_DOUBLE_EQ(t.errors[6].max, 200.0);
  EXPECT_EQ(t.errors_successful[6].count, 2u);
  EXPECT_DOUBLE_EQ(t.errors_successful[6].mean, 20.0);
  EXPECT_DOUBLE_EQ(t.time_ms.mean, 30.0);
  EXPECT_DOUBLE_EQ(t.time_ms.median, 20.0);
  EXPECT_DOUBLE_EQ(t.map_time_ms.mean, 1.0);
  EXPECT_DOUBLE_EQ(t.registration_time_ms.mean, 29.0);
  EXPECT_DOUBLE_EQ(t.iterations.mean, 10.0);
}

TEST(ComputeTotals, WithoutTruthHasNoRates) {
  std::vector<PairResult> results = {Pair(0.1, true, 10.0)};
  results[0].has_truth = false;
  const SequenceTotals t = ComputeTotals(results);
  EXPECT_FALSE(t.has_truth);
  EXPECT_EQ(t.successes, 0u);
  EXPECT_EQ(t.success_rate_percent, 0.0);
  EXPECT_EQ(t.errors[6].count, 0u);
  EXPECT_EQ(t.time_ms.count, 1u);
}

TEST(ComputeTotals, EmptyRun) {
  const SequenceTotals t = ComputeTotals({});
  EXPECT_EQ(t.pairs, 0u);
  EXPECT_FALSE(t.has_truth);
}

}  // namespace
}  // namespace mlndt
