#include "lab/bench/bench_run.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Pose(double x, double yaw_deg) {
  Isometry3d pose = Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, 0.0, 0.0);
  pose.linear() =
      Eigen::AngleAxisd(yaw_deg / kRadToDeg, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  return pose;
}

TEST(ScoreEstimate, ErrorsAndSuccessAgainstTheThresholds) {
  BenchEstimate e;
  e.reference_from_input = Pose(1.1, 0.5);
  e.usable = true;
  e.converged = true;
  e.time_ms = 12.0;
  e.iterations = 7;
  e.point_iterations = 123456;
  const BenchThresholds thresholds{0.2, 1.0};
  const BenchRun r = ScoreEstimate(e, Pose(1.0, 0.0), thresholds);
  EXPECT_NEAR(r.translation_error_m, 0.1, 1e-12);
  EXPECT_NEAR(r.rotation_error_deg, 0.5, 1e-9);
  EXPECT_TRUE(r.success);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 7);
  EXPECT_EQ(r.point_iterations, 123456);
  EXPECT_EQ(r.time_ms, 12.0);
  EXPECT_TRUE(std::isnan(r.nees));  // No covariance.

  // Over either threshold, or not usable: no success.
  e.reference_from_input = Pose(1.3, 0.0);
  EXPECT_FALSE(ScoreEstimate(e, Pose(1.0, 0.0), thresholds).success);
  e.reference_from_input = Pose(1.0, 1.5);
  EXPECT_FALSE(ScoreEstimate(e, Pose(1.0, 0.0), thresholds).success);
  e.reference_from_input = Pose(1.0, 0.0);
  e.usable = false;
  EXPECT_FALSE(ScoreEstimate(e, Pose(1.0, 0.0), thresholds).success);
}

// NEES = e^T P^-1 e: an error of 2 sigma in x alone gives 4.
TEST(ScoreEstimate, NeesOfAUsableRunWithACovariance) {
  BenchEstimate e;
  e.reference_from_input = Pose(1.2, 0.0);
  e.usable = true;
  e.covariance = Matrix6d::Identity() * 0.01;  // sigma 0.1 m / 0.1 rad.
  const BenchRun r = ScoreEstimate(e, Pose(1.0, 0.0), BenchThresholds());
  EXPECT_NEAR(r.nees, 4.0, 1e-9);
  e.usable = false;
  EXPECT_TRUE(std::isnan(ScoreEstimate(e, Pose(1.0, 0.0), {}).nees));
}

}  // namespace
}  // namespace mlndt
