// PCL clouds and matrices into mlndt's types (mlndt/pcl/conversions.h): the
// points equal mlndt's reader's, bit for bit, and a transformation that is
// not rigid is refused.

#include "mlndt/pcl/conversions.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>
#include <string>

#include "mlndt/cloud/io.h"

namespace mlndt {
namespace pcl {
namespace {

const std::string kDataDir = MLNDT_PCL_TEST_DATA_DIR;

TEST(ToPointCloud, DropsNonFinitePointsAndKeepsTheOrder) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  ::pcl::PointCloud<::pcl::PointXYZI> cloud;
  cloud.push_back(::pcl::PointXYZI(0.1f, -2.5f, 3.0f, 7.0f));
  cloud.push_back(::pcl::PointXYZI(nan, 0.0f, 0.0f, 0.0f));
  cloud.push_back(::pcl::PointXYZI(1.0f, inf, 0.0f, 0.0f));
  cloud.push_back(::pcl::PointXYZI(4.0f, 5.0f, -inf, 0.0f));
  cloud.push_back(::pcl::PointXYZI(1e-7f, 1e7f, -0.3f, 1.0f));
  size_t dropped = 0;
  const PointCloud points = ToPointCloud(cloud, &dropped);
  EXPECT_EQ(dropped, 3u);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], Eigen::Vector3d(static_cast<double>(0.1f), -2.5, 3.0));
  EXPECT_EQ(points[1],
            Eigen::Vector3d(static_cast<double>(1e-7f),
                            static_cast<double>(1e7f),
                            static_cast<double>(-0.3f)));
}

TEST(ToPointCloud, EmptyCloud) {
  size_t dropped = 5;
  EXPECT_TRUE(
      ToPointCloud(::pcl::PointCloud<::pcl::PointXYZ>(), &dropped).empty());
  EXPECT_EQ(dropped, 0u);
}

// PCL's PCD reader and mlndt's give the same points for the same file
// (x y z intensity on koide3, x y z on KITTI, binary_compressed on room).
void ExpectSameAsMlndtReader(const std::string& path) {
  SCOPED_TRACE(path);
  PointCloud read;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(path, &read, nullptr, &error)) << error;
  ::pcl::PointCloud<::pcl::PointXYZ> xyz;
  ::pcl::PointCloud<::pcl::PointXYZI> xyzi;
  ASSERT_EQ(::pcl::io::loadPCDFile(path, xyz), 0);
  ASSERT_EQ(::pcl::io::loadPCDFile(path, xyzi), 0);
  const PointCloud from_xyz = ToPointCloud(xyz);
  const PointCloud from_xyzi = ToPointCloud(xyzi);
  ASSERT_EQ(from_xyz.size(), read.size());
  ASSERT_EQ(from_xyzi.size(), read.size());
  for (size_t i = 0; i < read.size(); ++i) {
    ASSERT_EQ(from_xyz[i], read[i]) << "point " << i;
    ASSERT_EQ(from_xyzi[i], read[i]) << "point " << i;
  }
}

TEST(ToPointCloud, EqualsMlndtReaderOnTheBundledScans) {
  ExpectSameAsMlndtReader(kDataDir + "/koide3/251370668.pcd");
  ExpectSameAsMlndtReader(kDataDir + "/kitti/pcd/000000.pcd");
  ExpectSameAsMlndtReader(kDataDir + "/room/room_scan2.pcd");
}

TEST(ToIsometry, CastsARigidTransformation) {
  const Eigen::Matrix4f matrix =
      (Eigen::Translation3f(1.79387f, 0.720047f, 0.0f) *
       Eigen::AngleAxisf(0.6931f, Eigen::Vector3f::UnitZ()))
          .matrix();
  Isometry3d transform;
  std::string error;
  ASSERT_TRUE(ToIsometry(matrix, &transform, &error)) << error;
  EXPECT_EQ(transform.matrix(), matrix.cast<double>());
}

TEST(ToIsometry, RefusesWhatIsNotRigid) {
  const Eigen::Matrix4f identity = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f nan = identity;
  nan(0, 3) = std::numeric_limits<float>::quiet_NaN();
  Eigen::Matrix4f last_row = identity;
  last_row(3, 0) = 0.5f;
  Eigen::Matrix4f scaled = identity;
  scaled.topLeftCorner<3, 3>() *= 1.01f;
  Eigen::Matrix4f reflection = identity;
  reflection(2, 2) = -1.0f;
  for (const Eigen::Matrix4f& matrix : {nan, last_row, scaled, reflection}) {
    Isometry3d transform = Isometry3d::Identity();
    std::string error;
    EXPECT_FALSE(ToIsometry(matrix, &transform, &error)) << matrix;
    EXPECT_FALSE(error.empty());
  }
}

}  // namespace
}  // namespace pcl
}  // namespace mlndt
