#include "lab/runs/merged_cloud.h"

#include <gtest/gtest.h>

#include <fstream>

#include "mlndt/cloud/io.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// The bundled KITTI frames: 8 scans of 991,949 points in all (the size
// mlndt_scaling's default sizes stop below). The first scan stays where it
// is (up to rounding); the others are moved by the ground truth.
TEST(MergeScansInFirstFrame, MergesTheBundledKittiFrames) {
  PointCloud merged;
  size_t num_scans = 0;
  std::string error;
  ASSERT_TRUE(
      MergeScansInFirstFrame(testing::BundledDataPath("kitti/pcd"),
                             testing::BundledDataPath("kitti/poses_velo.txt"),
                             "",
                             &merged,
                             &num_scans,
                             &error))
      << error;
  EXPECT_EQ(num_scans, 8u);
  EXPECT_EQ(merged.size(), 991949u);
  PointCloud first;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000000.pcd"),
                             &first,
                             nullptr,
                             &error))
      << error;
  ASSERT_GT(first.size(), 0u);
  // P_0^-1 P_0 is the identity up to rounding.
  EXPECT_LT((merged.points().front() - first.points().front()).norm(), 1e-9);
  EXPECT_LT((merged.points()[first.size() - 1] - first.points().back()).norm(),
            1e-9);
  // 7 frames later the car has moved several metres: the centroid of the
  // merged cloud is not the first scan's.
  Eigen::Vector3d merged_mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : merged.points()) merged_mean += p;
  Eigen::Vector3d first_mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : first.points()) first_mean += p;
  merged_mean /= static_cast<double>(merged.size());
  first_mean /= static_cast<double>(first.size());
  EXPECT_GT((merged_mean - first_mean).norm(), 1.0);
}

TEST(MergeScansInFirstFrame, RefusesFewerPosesThanScans) {
  const std::string poses = testing::ScratchPath("two_poses.txt");
  {
    std::ofstream out(poses);
    out << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n";
  }
  PointCloud merged;
  size_t num_scans = 0;
  std::string error;
  EXPECT_FALSE(MergeScansInFirstFrame(testing::BundledDataPath("kitti/pcd"),
                                      poses,
                                      "",
                                      &merged,
                                      &num_scans,
                                      &error));
  EXPECT_NE(error.find("has 2 poses for 8 scans"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
