#include "tests/testing/kitti_bundle.h"

#include <gtest/gtest.h>

#include <string>

#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/io.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace testing {

PointCloud BundledKittiScan(int i, size_t stride) {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(
      BundledDataPath("kitti/pcd/00000" + std::to_string(i) + ".pcd"),
      &cloud,
      nullptr,
      &error))
      << error;
  if (stride <= 1) return cloud;
  PointCloud thinned;
  for (size_t k = 0; k < cloud.size(); k += stride) thinned.Add(cloud[k]);
  return thinned;
}

std::vector<Isometry3d> BundledKittiPoses() {
  Trajectory trajectory;
  std::string error;
  EXPECT_TRUE(ReadTrajectory(BundledDataPath("kitti/poses_velo.txt"),
                             TrajectoryFormat::KITTI,
                             &trajectory,
                             &error))
      << error;
  return trajectory.poses();
}

}  // namespace testing
}  // namespace mlndt
