// One point of mlndt_scaling (lab/experiments/scaling_measure.h), tested
// only through the tool before: two independent random subsets of N points
// of the bundled koide3 scan, the input moved by a known motion, registered
// from the identity; the result says N, the map's layers and cells, the
// verdict and the error against that motion, and is the same for the same
// seed.

#include "lab/experiments/scaling_measure.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

PointCloud Koide3Scan() {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(testing::BundledDataPath("koide3/251370668.pcd"),
                             &cloud,
                             nullptr,
                             &error))
      << error;
  return cloud;
}

// 0.3 m along x, 0.1 m along y, 2 deg of yaw.
Isometry3d Motion() {
  Vector6d xi;
  xi << 0.3, 0.1, 0.0, 0.0, 0.0, 2.0 * kDegToRad;
  return PoseVectorToIsometry(xi);
}

ScalingSettings OneRepetition() {
  ScalingSettings settings;
  settings.repetitions = 1;
  return settings;
}

TEST(MeasureSize, RecoversTheMotionOfTwoSubsetsOfTheKoide3Scan) {
  const PointCloud scan = Koide3Scan();
  SizeResult result;
  std::string error;
  ASSERT_TRUE(MeasureSize(OneRepetition(),
                          MatcherOptions(),
                          scan,
                          20000,
                          Motion(),
                          &result,
                          &error))
      << error;
  EXPECT_EQ(result.points, 20000u);
  EXPECT_GT(result.num_layers, 1);
  EXPECT_GT(result.finest_cells, 0u);
  EXPECT_GT(result.sampled_points, 0u);
  EXPECT_LE(result.sampled_points, 20000u);
  EXPECT_GT(result.iterations, 0);
  EXPECT_EQ(result.termination, TerminationType::CONVERGENCE) << result.message;
  EXPECT_LT(result.translation_error_m, 0.1);
  EXPECT_LT(result.rotation_error_deg, 0.5);
  EXPECT_TRUE(result.ok);
  EXPECT_GE(result.total_ms, result.solve_ms);
}

TEST(MeasureSize, TheSameSeedGivesTheSameSubsetsAndResult) {
  const PointCloud scan = Koide3Scan();
  SizeResult a, b, other_seed;
  std::string error;
  ScalingSettings settings = OneRepetition();
  ASSERT_TRUE(MeasureSize(
      settings, MatcherOptions(), scan, 8000, Motion(), &a, &error));
  ASSERT_TRUE(MeasureSize(
      settings, MatcherOptions(), scan, 8000, Motion(), &b, &error));
  settings.seed = 2;
  ASSERT_TRUE(MeasureSize(
      settings, MatcherOptions(), scan, 8000, Motion(), &other_seed, &error));
  EXPECT_EQ(a.translation_error_m, b.translation_error_m);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.finest_cells, b.finest_cells);
  // Other subsets: another map, another solution.
  EXPECT_NE(a.translation_error_m, other_seed.translation_error_m);
}

TEST(MeasureSize, AToleranceTheErrorExceedsIsABrokenSolve) {
  const PointCloud scan = Koide3Scan();
  ScalingSettings settings = OneRepetition();
  settings.max_translation_error_m = 0.0;  // No error is within it.
  SizeResult result;
  std::string error;
  ASSERT_TRUE(MeasureSize(
      settings, MatcherOptions(), scan, 8000, Motion(), &result, &error));
  EXPECT_GT(result.translation_error_m, 0.0);
  EXPECT_FALSE(result.ok);
}

TEST(MeasureSizes, MeasuresEverySizeInOrder) {
  const PointCloud scan = Koide3Scan();
  std::vector<SizeResult> results;
  std::string error;
  ASSERT_TRUE(MeasureSizes(OneRepetition(),
                           MatcherOptions(),
                           scan,
                           {5000, 15000},
                           Motion(),
                           nullptr,
                           &results,
                           &error))
      << error;
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].points, 5000u);
  EXPECT_EQ(results[1].points, 15000u);
  EXPECT_LT(results[0].finest_cells, results[1].finest_cells);
}

}  // namespace
}  // namespace mlndt
