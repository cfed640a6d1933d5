#include "lab/io/ros_bag_scans.h"

#include <gtest/gtest.h>

#include "mlndt/cloud/io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::BundledDataPath;

std::vector<std::string> KittiScans(int n) {
  std::vector<std::string> scans;
  for (int i = 0; i < n; ++i) {
    scans.push_back(
        BundledDataPath("kitti/pcd/00000" + std::to_string(i) + ".pcd"));
  }
  return scans;
}

// The bag route gives the PCD route's points, one for one, with the header
// stamps and the per-point time field.
TEST(RosBagScans, BundledKittiScansReadPointForPointAsTheirPcdFiles) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("ros_bag_scans");
  const std::string bag = dir + "/kitti.bag";
  const std::vector<std::string> scans = KittiScans(2);
  std::string error;
  ASSERT_TRUE(testing::WriteTestBag(
      bag, "/velodyne_points", scans, "--point_time", &error))
      << error;
  std::unique_ptr<RosBagScans> reader;
  ASSERT_TRUE(RosBagScans::Open(bag, "/velodyne_points", &reader, &error))
      << error;
  ASSERT_EQ(reader->size(), scans.size());
  for (size_t i = 0; i < scans.size(); ++i) {
    PointCloud pcd;
    ASSERT_TRUE(ReadPointCloud(scans[i], &pcd, nullptr, &error)) << error;
    BagScan scan;
    ASSERT_TRUE(reader->Read(i, &scan, &error)) << error;
    EXPECT_NEAR(scan.stamp_s, 1000.0 + 0.1 * static_cast<double>(i), 1e-6);
    EXPECT_EQ(scan.frame_id, "lidar");
    EXPECT_EQ(scan.time_field, "time");
    ASSERT_EQ(scan.cloud.size(), pcd.size());
    ASSERT_EQ(scan.point_times_s.size(), pcd.size());
    for (size_t k = 0; k < pcd.size(); ++k) {
      ASSERT_EQ(scan.cloud[k], pcd[k]) << "scan " << i << " point " << k;
      ASSERT_EQ(scan.point_times_s[k],
                static_cast<double>(static_cast<float>(k * 1e-6)))
          << "point " << k;
    }
  }
  BagScan beyond;
  EXPECT_FALSE(reader->Read(scans.size(), &beyond, &error));
  EXPECT_NE(error.find("the topic has 2 messages"), std::string::npos) << error;
}

TEST(RosBagScans, MissingTopicWrongTypeAndMissingFileNameWhatTheBagHas) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("ros_bag_scans");
  const std::string bag = dir + "/one.bag";
  std::string error;
  ASSERT_TRUE(testing::WriteTestBag(
      bag, "/points", KittiScans(1), "--other_topic=/note", &error))
      << error;
  std::unique_ptr<RosBagScans> reader;
  EXPECT_FALSE(RosBagScans::Open(bag, "/velodyne_points", &reader, &error));
  EXPECT_NE(error.find("no messages on topic '/velodyne_points'"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("/points (sensor_msgs/PointCloud2)"), std::string::npos)
      << error;
  EXPECT_FALSE(RosBagScans::Open(bag, "/note", &reader, &error));
  EXPECT_NE(error.find("topic /note is std_msgs/String, not "
                       "sensor_msgs/PointCloud2"),
            std::string::npos)
      << error;
  EXPECT_FALSE(
      RosBagScans::Open(dir + "/missing.bag", "/points", &reader, &error));
  EXPECT_NE(error.find("missing.bag"), std::string::npos) << error;
  EXPECT_EQ(reader, nullptr);
}

}  // namespace
}  // namespace mlndt
