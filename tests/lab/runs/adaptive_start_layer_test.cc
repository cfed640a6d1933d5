// The adaptive start layer: the guess check and the exact switching points
// of the running fail rate (strictly above 5 % and 20 %).

#include "lab/runs/adaptive_start_layer.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

void RecordMany(int count, bool failed, AdaptiveStartLayer* rule) {
  for (int k = 0; k < count; ++k) rule->Record(failed);
}

TEST(AdaptiveStartLayer, StartsOnTheLastLayer) {
  AdaptiveStartLayer rule{AdaptiveStartLayerOptions()};
  EXPECT_EQ(rule.running_fail_rate(), 0.0);
  EXPECT_EQ(rule.StartLayer(), 0);
  RecordMany(10, false, &rule);
  EXPECT_EQ(rule.StartLayer(), 0);
}

TEST(AdaptiveStartLayer, OneLayerCoarserOnlyAboveFivePercent) {
  AdaptiveStartLayer rule{AdaptiveStartLayerOptions()};
  RecordMany(18, false, &rule);
  rule.Record(true);  // 1 / 19 = 5.3 %.
  EXPECT_DOUBLE_EQ(rule.running_fail_rate(), 1.0 / 19.0);
  EXPECT_EQ(rule.StartLayer(), -1);
  rule.Record(false);  // 1 / 20 = 5 % exactly: not above.
  EXPECT_EQ(rule.running_fail_rate(), 0.05);
  EXPECT_EQ(rule.StartLayer(), 0);
  rule.Record(false);  // 1 / 21: decays as successes accumulate.
  EXPECT_EQ(rule.StartLayer(), 0);
}

TEST(AdaptiveStartLayer, TwoLayersCoarserOnlyAboveTwentyPercent) {
  AdaptiveStartLayer rule{AdaptiveStartLayerOptions()};
  RecordMany(4, false, &rule);
  rule.Record(true);  // 1 / 5 = 20 % exactly: above 5 % only.
  EXPECT_EQ(rule.running_fail_rate(), 0.2);
  EXPECT_EQ(rule.StartLayer(), -1);
  rule.Record(true);  // 2 / 6.
  EXPECT_EQ(rule.StartLayer(), -2);
  RecordMany(4, false, &rule);  // 2 / 10 = 20 %.
  EXPECT_EQ(rule.StartLayer(), -1);
  RecordMany(30, false, &rule);  // 2 / 40 = 5 %.
  EXPECT_EQ(rule.StartLayer(), 0);
}

TEST(AdaptiveStartLayer, ThresholdsAreOptions) {
  AdaptiveStartLayerOptions options;
  options.fail_rate_thresholds = {0.1, 0.3, 0.6};
  AdaptiveStartLayer rule(options);
  rule.Record(true);  // 100 %: all three.
  EXPECT_EQ(rule.StartLayer(), -3);
  rule.Record(false);  // 50 %.
  EXPECT_EQ(rule.StartLayer(), -2);
}

TEST(CheckGuess, FailsBeyondEitherLimitOrWhenNotUsable) {
  const AdaptiveStartLayerOptions options;  // 1 m, 15 deg.
  const Isometry3d guess = Isometry3d::Identity();
  const auto at = [](double tx, double yaw_deg) {
    return PoseVectorToIsometry(PoseVectorFromDegrees(tx, 0, 0, 0, 0, yaw_deg));
  };
  GuessCheck check = CheckGuess(options, true, guess, at(0.9, 14));
  EXPECT_NEAR(check.deviation_m, 0.9, 1e-12);
  EXPECT_NEAR(check.deviation_deg, 14.0, 1e-9);
  EXPECT_FALSE(check.failed);
  EXPECT_TRUE(CheckGuess(options, true, guess, at(1.1, 0)).failed);
  EXPECT_TRUE(CheckGuess(options, true, guess, at(0, 16)).failed);
  EXPECT_TRUE(CheckGuess(options, false, guess, guess).failed);
}

}  // namespace
}  // namespace mlndt
