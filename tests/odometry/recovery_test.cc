#include "mlndt/odometry/recovery.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d Pose(double x, double y, double yaw_deg) {
  return PoseVectorToIsometry(PoseVectorFromDegrees(x, y, 0, 0, 0, yaw_deg));
}

// Halfway in time is halfway in translation and in rotation; the ends are
// the registered poses themselves.
TEST(InterpolatePose, FollowsTheMotionBetweenTheNeighboursByTime) {
  const Isometry3d before = Pose(1.0, 2.0, 10.0);
  const Isometry3d after = before * Pose(2.0, 0.0, 40.0);
  const Isometry3d half = InterpolatePose(before, 10.0, after, 12.0, 11.0);
  EXPECT_NEAR(RotationErrorRad(before, half) * kRadToDeg, 20.0, 1e-9);
  EXPECT_NEAR(TranslationErrorM(before, half), 1.0, 1e-9);
  const Isometry3d quarter = InterpolatePose(before, 10.0, after, 12.0, 10.5);
  EXPECT_NEAR(RotationErrorRad(before, quarter) * kRadToDeg, 10.0, 1e-9);
  EXPECT_TRUE(
      InterpolatePose(before, 10.0, after, 12.0, 10.0).isApprox(before));
  EXPECT_TRUE(InterpolatePose(before, 10.0, after, 12.0, 12.0).isApprox(after));
}

// The last registered pose first, then the prediction and the last pose
// turned both ways about the sensor's z axis; the count is the option's.
TEST(SearchStarts, TriesTheLastPoseThenTurnedStarts) {
  RecoveryOptions options;
  options.max_search_starts = 5;
  options.yaw_step_deg = 15.0;
  const Isometry3d predicted = Pose(1.0, 0.0, 20.0);
  const Isometry3d last = Pose(0.5, 0.0, 5.0);
  const std::vector<Isometry3d> starts = SearchStarts(options, predicted, last);
  ASSERT_EQ(starts.size(), 5u);
  EXPECT_TRUE(starts[0].isApprox(last));
  EXPECT_TRUE(starts[1].isApprox(Pose(1.0, 0.0, 35.0)));
  EXPECT_TRUE(starts[2].isApprox(Pose(1.0, 0.0, 5.0)));
  EXPECT_TRUE(starts[3].isApprox(Pose(0.5, 0.0, 20.0)));
  EXPECT_TRUE(starts[4].isApprox(Pose(0.5, 0.0, -10.0)));
  options.max_search_starts = 0;
  EXPECT_TRUE(SearchStarts(options, predicted, last).empty());
}

TEST(RecoveryOptions, RefusesMoreStartsThanThereAre) {
  RecoveryOptions options;
  options.max_search_starts = 6;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_search_starts"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
