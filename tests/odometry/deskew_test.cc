#include "mlndt/odometry/deskew.h"

#include <gtest/gtest.h>

#include "mlndt/cloud/io.h"
#include "mlndt/odometry/motion_prediction.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// A real KITTI sweep skewed by a known motion (5 m/s forward while turning
// at 0.5 rad/s, 0.1 s sweep: each point in the frame of its own instant) is
// moved back into the frame of the stamp.
TEST(DeskewScan, UndoesTheMotionOfAKnownVelocityOnAKittiSweep) {
  PointCloud cloud;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000000.pcd"),
                             &cloud,
                             nullptr,
                             &error))
      << error;
  Vector6d velocity;
  velocity << 5.0, 0.2, 0.0, 0.0, 0.01, 0.5;
  std::vector<double> times;
  PointCloud skewed;
  for (size_t k = 0; k < cloud.size(); ++k) {
    times.push_back(0.1 * static_cast<double>(k) /
                    static_cast<double>(cloud.size()));
    // p_stamp = exp(t v) p_t, so p_t = exp(t v)^-1 p_stamp.
    skewed.Add(TwistToMotion(velocity * times.back()).inverse() * cloud[k]);
  }
  double largest_skew = 0.0;
  for (size_t k = 0; k < cloud.size(); ++k) {
    largest_skew = std::max(largest_skew, (skewed[k] - cloud[k]).norm());
  }
  EXPECT_GT(largest_skew, 0.5);  // The skew is far above the tolerance.
  ASSERT_TRUE(DeskewScan(velocity, times, &skewed, &error)) << error;
  for (size_t k = 0; k < cloud.size(); ++k) {
    ASSERT_LT((skewed[k] - cloud[k]).norm(), 1e-9) << "point " << k;
  }
}

TEST(DeskewScan, RefusesTimesThatDoNotMatchThePoints) {
  PointCloud cloud({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)});
  std::string error;
  EXPECT_FALSE(DeskewScan(Vector6d::Ones(), {0.0}, &cloud, &error));
  EXPECT_EQ(error, "deskew: 1 point times for 2 points");
  EXPECT_EQ(cloud[1], Eigen::Vector3d(4, 5, 6));
}

// A point without a finite time (a driver's marker, a corrupt field) cannot
// be moved to the stamp's frame: it is removed and counted, the others are
// deskewed.
TEST(DeskewScan, RemovesPointsWithoutAFiniteTime) {
  PointCloud cloud({Eigen::Vector3d(1, 2, 3),
                    Eigen::Vector3d(4, 5, 6),
                    Eigen::Vector3d(7, 8, 9)});
  Vector6d velocity = Vector6d::Zero();
  velocity(0) = 10.0;  // 10 m/s along x.
  std::string error;
  size_t removed = 0;
  ASSERT_TRUE(
      DeskewScan(velocity, {0.1, NAN, INFINITY}, &cloud, &error, &removed))
      << error;
  EXPECT_EQ(removed, 2u);
  ASSERT_EQ(cloud.size(), 1u);
  EXPECT_TRUE(cloud[0].isApprox(Eigen::Vector3d(2, 2, 3)));
}

}  // namespace
}  // namespace mlndt
