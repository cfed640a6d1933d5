// mlndt_sequence reads a ROS 1 bag (--bag --topic) as it reads a folder: a
// bag written from the bundled KITTI frames 0-7 gives the same poses, and
// its TUM trajectory carries the bag's header stamps.

#include <gtest/gtest.h>

#include "lab/eval/trajectory_io.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ReadWholeFile;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

TEST(MlndtSequenceBag, BagOfTheKittiFramesGivesTheFolderPoses) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_sequence_bag");
  const std::string pcd = testing::BundledDataPath("kitti/pcd");
  std::vector<std::string> scans;
  for (int i = 0; i < 8; ++i) {
    scans.push_back(pcd + "/00000" + std::to_string(i) + ".pcd");
  }
  std::string error;
  ASSERT_TRUE(testing::WriteTestBag(
      dir + "/kitti.bag", "/velodyne_points", scans, "--point_time", &error))
      << error;
  const std::string gt =
      " --gt_poses=" + Quote(testing::BundledDataPath("kitti/poses_velo.txt"));
  const ToolRun folder =
      RunTool("mlndt_sequence",
              "--scans=" + Quote(pcd) + gt +
                  " --output_dir=" + Quote(dir + "/folder") + " --plots=false");
  const ToolRun bag = RunTool(
      "mlndt_sequence",
      "--bag=" + Quote(dir + "/kitti.bag") + " --topic=/velodyne_points" + gt +
          " --output_dir=" + Quote(dir + "/bag") + " --plots=false");
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  ASSERT_EQ(bag.exit_code, 0) << bag.err;
  const std::string poses = ReadWholeFile(dir + "/bag/trajectory_kitti.txt");
  EXPECT_EQ(std::count(poses.begin(), poses.end(), '\n'), 8);
  EXPECT_EQ(poses, ReadWholeFile(dir + "/folder/trajectory_kitti.txt"));
  // The folder had no times: its TUM file says its stamps are indices.
  EXPECT_TRUE(TumStampsAreScanIndices(dir + "/folder/trajectory_tum.txt"));
  EXPECT_FALSE(TumStampsAreScanIndices(dir + "/bag/trajectory_tum.txt"));
  Trajectory tum;
  ASSERT_TRUE(ReadTrajectory(
      dir + "/bag/trajectory_tum.txt", TrajectoryFormat::TUM, &tum, &error))
      << error;
  ASSERT_EQ(tum.size(), 8u);
  EXPECT_NEAR(tum.timestamp_s(0), 1000.0, 1e-6);
  EXPECT_NEAR(tum.timestamp_s(7), 1000.7, 1e-6);
  // A topic the bag does not have: exit 2, naming the topics it has.
  const ToolRun wrong =
      RunTool("mlndt_sequence",
              "--bag=" + Quote(dir + "/kitti.bag") +
                  " --topic=/points --output_dir=" + Quote(dir + "/wrong") +
                  " --plots=false");
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("/velodyne_points (sensor_msgs/PointCloud2)"),
            std::string::npos)
      << wrong.err;
}

}  // namespace
}  // namespace mlndt
