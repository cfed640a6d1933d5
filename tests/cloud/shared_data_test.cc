// Loads every scan and pose file of the shared data set (MLNDT_DATA_DIR, see
// tests/testing/test_data.h) and checks the counts its README.md files give,
// plus a few geometric facts that catch a wrong axis, unit or sign.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

PointCloud ReadCloud(const std::string& path, size_t expected_points) {
  PointCloud cloud;
  ReadCloudInfo info;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(path, &cloud, &info, &error)) << error;
  EXPECT_EQ(cloud.size(), expected_points) << path;
  EXPECT_EQ(info.points_in_file, expected_points) << path;
  EXPECT_EQ(info.dropped_non_finite, 0u) << path;
  return cloud;
}

// The `fraction` quantile of one coordinate.
double Quantile(const PointCloud& cloud, int axis, double fraction) {
  std::vector<double> values;
  values.reserve(cloud.size());
  for (const Eigen::Vector3d& p : cloud.points()) values.push_back(p[axis]);
  const size_t k = static_cast<size_t>(fraction * (values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

// Lower edge of the most populated 10 cm slab of one coordinate (for z: the
// ground or floor height).
double ModeSlab(const PointCloud& cloud, int axis) {
  std::map<long, int> histogram;
  for (const Eigen::Vector3d& p : cloud.points()) {
    ++histogram[static_cast<long>(std::floor(p[axis] * 10.0))];
  }
  const auto best = std::max_element(
      histogram.begin(), histogram.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
      });
  return best->first / 10.0;
}

// ---- KITTI 00, frames 0-7
// -------------------------------------------------------

TEST(SharedData, KittiFramesHaveReadmeCounts) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const size_t counts[8] = {
      124668, 124605, 124478, 124167, 123969, 123924, 123373, 122765};
  for (int i = 0; i < 8; ++i) {
    ReadCloud(dir + "/kitti00_frames_0000_0007/pcd/00000" + std::to_string(i) +
                  ".pcd",
              counts[i]);
  }
}

TEST(SharedData, KittiFrameZeroGeometry) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const PointCloud cloud =
      ReadCloud(dir + "/kitti00_frames_0000_0007/pcd/000000.pcd", 124668);
  // Velodyne frame, metres: tens of metres around, a few metres high.
  const Eigen::Vector3d extent = BoundingBox(cloud).sizes();
  EXPECT_GT(extent.x(), 100.0);
  EXPECT_GT(extent.y(), 50.0);
  EXPECT_LT(extent.z(), 20.0);
  EXPECT_LT(BoundingBox(cloud).max().norm(), 150.0);  // Ranges up to ~80 m.
  // The road is the most populated height, ~1.73 m below the sensor.
  const double ground = ModeSlab(cloud, 2);
  EXPECT_GT(ground, -2.0);
  EXPECT_LT(ground, -1.5);
}

TEST(SharedData, KittiPosesAndCalibration) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const std::string folder = dir + "/kitti00_frames_0000_0007/";
  std::vector<Eigen::Isometry3d> velo, cam0;
  Eigen::Isometry3d cam0_from_velo;
  std::string error;
  ASSERT_TRUE(ReadKittiPoses(folder + "poses_velo.txt", &velo, &error))
      << error;
  ASSERT_TRUE(ReadKittiPoses(folder + "poses_cam0.txt", &cam0, &error))
      << error;
  ASSERT_TRUE(ReadKittiCalibTr(folder + "calib.txt", &cam0_from_velo, &error))
      << error;
  ASSERT_EQ(velo.size(), 8u);
  ASSERT_EQ(cam0.size(), 8u);

  // The Tr: value quoted in the README, row-major.
  const double readme_tr[12] = {4.276802385584e-04,
                                -9.999672484946e-01,
                                -8.084491683471e-03,
                                -1.198459927713e-02,
                                -7.210626507497e-03,
                                8.081198471645e-03,
                                -9.999413164504e-01,
                                -5.403984729748e-02,
                                9.999738645903e-01,
                                4.859485810390e-04,
                                -7.206933692422e-03,
                                -2.921968648686e-01};
  // The reader re-orthonormalises what is not a rotation to 1e-12
  // (mlndt/common/rigid_transform.h). KITTI's Tr is a rotation only to
  // about 1e-7 whatever its 13 digits: entries move by up to 4.7e-8.
  for (int i = 0; i < 12; ++i) {
    EXPECT_NEAR(cam0_from_velo.matrix()(i / 4, i % 4), readme_tr[i], 1e-7)
        << "entry " << i;
  }

  // README: V_i = Tr^-1 * P_i * Tr (poses_velo.txt is written with 10 digits).
  for (int i = 0; i < 8; ++i) {
    const Eigen::Matrix4d derived =
        (cam0_from_velo.inverse(Eigen::Affine) * cam0[i] * cam0_from_velo)
            .matrix();
    EXPECT_LT((derived - velo[i].matrix()).cwiseAbs().maxCoeff(), 1e-5)
        << "frame " << i;
  }
  // Frame 0 -> 1 moves ~0.86 m forward.
  const Eigen::Vector3d step = (velo[0].inverse() * velo[1]).translation();
  EXPECT_LT((step - Eigen::Vector3d(0.859, 0.047, 0.022)).norm(), 2e-3)
      << step.transpose();
}

// ---- koide3 Velodyne pair
// --------------------------------------------------------

TEST(SharedData, KoidePairPcdAndPlyAgree) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const std::string folder = dir + "/koide3_velodyne_pair/";
  // PLY headers: "element vertex 69088" (target.ply), 69792 (source.ply).
  const PointCloud target_pcd = ReadCloud(folder + "251370668.pcd", 69088);
  const PointCloud source_pcd = ReadCloud(folder + "251371071.pcd", 69792);
  const PointCloud target_ply = ReadCloud(folder + "target.ply", 69088);
  const PointCloud source_ply = ReadCloud(folder + "source.ply", 69792);
  // The PLY files are the same float32 points as the PCD files.
  EXPECT_TRUE(target_ply.points() == target_pcd.points());
  EXPECT_TRUE(source_ply.points() == source_pcd.points());
}

// ---- PCL room scans (binary_compressed)
// -------------------------------------------

TEST(SharedData, PclRoomScansBinaryCompressed) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const std::string folder = dir + "/pcl_room_scans/";
  for (const auto& [name, count] : std::vector<std::pair<std::string, size_t>>{
           {"room_scan1.pcd", 112586}, {"room_scan2.pcd", 112624}}) {
    const PointCloud cloud = ReadCloud(folder + name, count);
    // A room: tens of metres across at most, a few metres high.
    const Eigen::Vector3d extent = BoundingBox(cloud).sizes();
    EXPECT_GT(extent.x(), 5.0) << name;
    EXPECT_LT(extent.maxCoeff(), 50.0) << name;
    EXPECT_LT(extent.z(), 5.0) << name;
  }
}

// ---- 3DTK example scans
// ----------------------------------------------------------

TEST(SharedData, ThreeDtkScansConvertToZUpMetres) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  for (const char* name : {"scan000", "scan001", "scan002"}) {
    const PointCloud cloud =
        ReadCloud(dir + "/3dtk_example_scans/" + name + ".3d", 81360);
    // The scanner sees only its forward half space (3DTK z >= 0 -> x >= 0).
    EXPECT_GE(BoundingBox(cloud).min().x(), -1e-9) << name;
    // Metres: the farthest readings are 3DTK's 32.77 m saturation value.
    EXPECT_LT(BoundingBox(cloud).max().norm(), 60.0) << name;
    // Up is z: the floor is the most populated height, below the sensor.
    const double floor = ModeSlab(cloud, 2);
    EXPECT_GT(floor, -0.7) << name;
    EXPECT_LT(floor, -0.2) << name;
    // And the vertical spread (1-99 %) is smaller than both horizontal ones.
    double spread[3];
    for (int axis = 0; axis < 3; ++axis) {
      spread[axis] = Quantile(cloud, axis, 0.99) - Quantile(cloud, axis, 0.01);
    }
    EXPECT_LT(spread[2], spread[0]) << name;
    EXPECT_LT(spread[2], spread[1]) << name;
  }
}

TEST(SharedData, ThreeDtkPosesMoveForward) {
  MLNDT_REQUIRE_SHARED_DATA(dir);
  const std::string folder = dir + "/3dtk_example_scans/";
  Eigen::Isometry3d poses[3];
  for (int i = 0; i < 3; ++i) {
    std::string error;
    ASSERT_TRUE(Read3dtkPose(
        folder + "scan00" + std::to_string(i) + ".pose", &poses[i], &error))
        << error;
    // Odometry of a ground robot: small rotations only.
    EXPECT_LT(Eigen::AngleAxisd(poses[i].linear()).angle(), 3.0 * M_PI / 180.0);
  }
  EXPECT_TRUE(poses[0].isApprox(Eigen::Isometry3d::Identity()));
  // README: about 1.6-1.8 m forward (+z in 3DTK, +x here) between scans.
  const Eigen::Vector3d t1 = poses[1].translation(),
                        t2 = poses[2].translation();
  EXPECT_NEAR(t1.x(), 1.569, 1e-3);
  EXPECT_NEAR(t2.x(), 3.380, 1e-3);
  EXPECT_LT(t1.tail<2>().norm(), 0.2);
  EXPECT_LT(t2.tail<2>().norm(), 0.2);
}

}  // namespace
}  // namespace mlndt
