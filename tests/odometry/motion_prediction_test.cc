#include "mlndt/odometry/motion_prediction.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Pose(double x, double y, double yaw_deg) {
  return PoseVectorToIsometry(PoseVectorFromDegrees(x, y, 0, 0, 0, yaw_deg));
}

// The velocity is per second: a scan twice as far in time is predicted
// twice as far along (uneven keyframe spacing).
TEST(MotionPredictor, ExtrapolatesByTimeNotByScanCount) {
  MotionPredictor predictor{MotionPredictionOptions()};
  EXPECT_TRUE(predictor.Predict(3.0).isApprox(Isometry3d::Identity()));
  predictor.AddPose(10.0, Isometry3d::Identity(), Isometry3d::Identity());
  const Isometry3d second = Pose(1.0, 0.0, 0.0);
  predictor.AddPose(10.5, Isometry3d::Identity(), second);
  // 2 m/s along x: at 11.5 s, 2 m beyond the second pose.
  EXPECT_NEAR(predictor.Predict(11.5).translation().x(), 3.0, 1e-12);
  EXPECT_NEAR(predictor.Predict(11.0).translation().x(), 2.0, 1e-12);
  EXPECT_NEAR(predictor.Velocity()(0), 2.0, 1e-12);
}

// The uncertainty is the recent model error times the factor, within the
// bounds: the maximum before any error is known, the floor on a straight
// constant-velocity drive, and larger after a swerve.
TEST(MotionPredictor, UncertaintyFollowsRecentModelErrors) {
  MotionPredictionOptions options;
  MotionPredictor predictor(options);
  EXPECT_EQ(predictor.Uncertainty().translation_m, options.max_translation_m);
  for (int k = 0; k < 4; ++k) {
    const double t = 0.1 * k;
    predictor.AddPose(t, predictor.Predict(t), Pose(k * 1.0, 0, 0));
  }
  EXPECT_EQ(predictor.Uncertainty().translation_m, options.min_translation_m);
  EXPECT_EQ(predictor.Uncertainty().rotation_deg, options.min_rotation_deg);
  const Isometry3d predicted = predictor.Predict(0.4);
  predictor.AddPose(0.4, predicted, Pose(4.0, 0.3, 5.0));  // 0.3 m, 5 deg off.
  EXPECT_NEAR(predictor.Uncertainty().translation_m, 0.6, 1e-9);
  EXPECT_NEAR(predictor.Uncertainty().rotation_deg, 10.0, 1e-9);
}

// Skipped scans (no pose) leave the prediction extrapolating from the last
// pose by time, and each widens the uncertainty by one step's; the next
// pose's model error counts per step of the gap, and resets the growth.
TEST(MotionPredictor, UncertaintyGrowsWithEachSkippedScan) {
  MotionPredictionOptions options;
  MotionPredictor predictor(options);
  for (int k = 0; k < 4; ++k) {
    const double t = 0.1 * k;
    predictor.AddPose(t, predictor.Predict(t), Pose(k * 1.0, 0, 0));
  }
  const Isometry3d predicted = predictor.Predict(0.4);
  predictor.AddPose(0.4, predicted, Pose(4.0, 0.1, 1.0));  // 0.1 m, 1 deg.
  EXPECT_NEAR(predictor.Uncertainty().translation_m, 0.2, 1e-9);
  EXPECT_NEAR(predictor.Uncertainty().rotation_deg, 2.0, 1e-9);
  predictor.SkipScan();
  predictor.SkipScan();
  EXPECT_EQ(predictor.skipped(), 2u);
  EXPECT_NEAR(predictor.Uncertainty().translation_m, 0.6, 1e-9);
  EXPECT_NEAR(predictor.Uncertainty().rotation_deg, 6.0, 1e-9);
  // Still extrapolated from the last pose at 10 m/s (1 m per 0.1 s), but
  // over one step (0.1 s) at most.
  EXPECT_NEAR(predictor.Predict(0.7).translation().x(), 5.0, 0.05);
  EXPECT_NEAR(predictor.Predict(0.45).translation().x(), 4.5, 0.05);
  for (int k = 0; k < 20; ++k) predictor.SkipScan();
  EXPECT_EQ(predictor.Uncertainty().translation_m, options.max_translation_m);
  EXPECT_EQ(predictor.Uncertainty().rotation_deg, options.max_rotation_deg);
  // After 22 skipped scans 0.3 m off: per step of the gap that is below the
  // window's 0.1 m.
  const Isometry3d after_gap = predictor.Predict(0.7);
  predictor.AddPose(0.7, after_gap, after_gap * Pose(0.3, 0.0, 0.0));
  EXPECT_EQ(predictor.skipped(), 0u);
  EXPECT_NEAR(predictor.Uncertainty().translation_m, 0.2, 1e-9);
}

TEST(MotionPredictionOptions, RefusesBoundsOutOfOrder) {
  MotionPredictionOptions options;
  options.max_translation_m = 0.05;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_translation_m"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
