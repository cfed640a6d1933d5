#include "lab/eval/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mlndt {
namespace {

Isometry3d At(double x, double y, double z) {
  Isometry3d pose = Isometry3d::Identity();
  pose.translation() = Vector3d(x, y, z);
  return pose;
}

TEST(Trajectory, PosesAloneUseTheIndexAsTime) {
  const Trajectory trajectory({At(0, 0, 0), At(1, 0, 0), At(2, 0, 0)});
  ASSERT_EQ(trajectory.size(), 3u);
  EXPECT_EQ(trajectory.timestamps_s(), (std::vector<double>{0.0, 1.0, 2.0}));
  EXPECT_EQ(trajectory.world_from_sensor(2).translation(), Vector3d(2, 0, 0));
}

TEST(Trajectory, AddKeepsTimeOrder) {
  Trajectory trajectory;
  EXPECT_TRUE(trajectory.empty());
  trajectory.Add(10.5, At(1, 2, 3));
  trajectory.Add(10.6, At(4, 5, 6));
  EXPECT_EQ(trajectory.timestamp_s(1), 10.6);
  EXPECT_EQ(trajectory.poses()[0].translation(), Vector3d(1, 2, 3));
}

TEST(TrajectoryDeathTest, AddRejectsTimeThatDoesNotIncrease) {
  Trajectory trajectory;
  trajectory.Add(1.0, At(0, 0, 0));
  EXPECT_DEATH(trajectory.Add(1.0, At(0, 0, 0)), "increase strictly");
  EXPECT_DEATH(trajectory.Add(0.5, At(0, 0, 0)), "increase strictly");
}

TEST(Trajectory, TryAddRefusesTimeThatDoesNotIncreaseWithoutAdding) {
  Trajectory trajectory;
  std::string error;
  ASSERT_TRUE(trajectory.TryAdd(1.0, At(0, 0, 0), &error)) << error;
  EXPECT_FALSE(trajectory.TryAdd(1.0, At(1, 0, 0), &error));
  EXPECT_NE(error.find("timestamp 1 after 1"), std::string::npos) << error;
  EXPECT_NE(error.find("increase strictly"), std::string::npos) << error;
  EXPECT_FALSE(trajectory.TryAdd(0.5, At(1, 0, 0), &error));
  EXPECT_FALSE(trajectory.TryAdd(std::nan(""), At(1, 0, 0), &error));
  EXPECT_EQ(trajectory.size(), 1u);
  EXPECT_TRUE(trajectory.TryAdd(1.5, At(1, 0, 0), &error)) << error;
  EXPECT_EQ(trajectory.size(), 2u);
}

TEST(PathDistancesM, SumsTheStepLengths) {
  const std::vector<double> d =
      PathDistancesM({At(0, 0, 0), At(3, 4, 0), At(3, 4, 12), At(3, 4, 12)});
  EXPECT_EQ(d, (std::vector<double>{0.0, 5.0, 17.0, 17.0}));
  EXPECT_TRUE(PathDistancesM({}).empty());
}

}  // namespace
}  // namespace mlndt
