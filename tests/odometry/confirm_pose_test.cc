#include "mlndt/odometry/confirm_pose.h"

#include <gtest/gtest.h>

#include <string>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Pose(double x, double y, double yaw_deg) {
  return PoseVectorToIsometry(PoseVectorFromDegrees(x, y, 0, 0, 0, yaw_deg));
}

// The second run starts beyond the pose along the correction: a short
// correction is continued until the move is the uncertainty, a long one by
// its own length; a part that did not move (here the rotation) stays.
TEST(ConfirmationStart, ContinuesTheCorrectionByTheUncertainty) {
  const PredictionUncertainty uncertainty{1.0, 10.0};
  const Isometry3d predicted = Pose(5.0, 0.0, 0.0);
  const Isometry3d short_start =
      ConfirmationStart(uncertainty, predicted, Pose(5.3, 0.0, 0.0));
  EXPECT_TRUE(short_start.isApprox(Pose(6.3, 0.0, 0.0), 1e-12));
  const Isometry3d long_start =
      ConfirmationStart(uncertainty, predicted, Pose(7.0, 0.0, 0.0));
  EXPECT_TRUE(long_start.isApprox(Pose(9.0, 0.0, 0.0), 1e-12));
  const Isometry3d turned_start =
      ConfirmationStart(uncertainty, predicted, Pose(5.0, 0.0, 1.0));
  EXPECT_TRUE(turned_start.isApprox(Pose(5.0, 0.0, 11.0), 1e-12));
}

// A correction within the fraction of the uncertainty stands unconfirmed;
// beyond it, or from a prediction at its largest uncertainty, it needs the
// second run; off, never.
TEST(NeedsConfirmation, LargeCorrectionsAndPredictionsAtTheMaximum) {
  ConfirmationOptions options;  // Fraction 0.5.
  const MotionPredictionOptions prediction;
  const PredictionUncertainty known{0.4, 10.0};
  const Isometry3d predicted = Pose(1.0, 2.0, 30.0);
  EXPECT_FALSE(NeedsConfirmation(
      options, prediction, known, predicted, Pose(1.1, 2.0, 33.0)));
  EXPECT_TRUE(NeedsConfirmation(
      options, prediction, known, predicted, Pose(1.3, 2.0, 30.0)));
  EXPECT_TRUE(NeedsConfirmation(
      options, prediction, known, predicted, Pose(1.0, 2.0, 36.0)));
  const PredictionUncertainty largest{prediction.max_translation_m,
                                      prediction.max_rotation_deg};
  EXPECT_TRUE(
      NeedsConfirmation(options, prediction, largest, predicted, predicted));
  options.enabled = false;
  EXPECT_FALSE(NeedsConfirmation(
      options, prediction, known, predicted, Pose(1.3, 2.0, 30.0)));
  options.enabled = true;
  options.min_correction_fraction = 0.0;
  EXPECT_TRUE(NeedsConfirmation(
      options, prediction, known, predicted, Pose(1.01, 2.0, 30.0)));
}

TEST(ConfirmationOptions, RefusesANegativeFraction) {
  ConfirmationOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.min_correction_fraction = -0.1;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("min_correction_fraction"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
