// Time stamps and bag input of the map tools (issue 27 item 15): the TUM
// trajectory of mlndt_localize carries the scans' times (a --times file,
// the bag's header stamps) or says in its header that its stamps are scan
// indices; mlndt_map builds the same map from a bag as from the folder.

#include <gtest/gtest.h>

#include <fstream>

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

std::string KittiPcd() { return testing::BundledDataPath("kitti/pcd"); }

std::string Chain(const std::string& dir) {
  const ToolRun chain = RunTool(
      "mlndt_eval",
      "chain " + Quote(testing::BundledDataPath("kitti/reference_pairs.json")) +
          " " + Quote(dir + "/chain.txt"));
  EXPECT_EQ(chain.exit_code, 0) << chain.err;
  return dir + "/chain.txt";
}

const char kMapFlags[] = " --min_range_m=3 --max_range_m=80 --voxel_size=0.2";

Trajectory ReadTum(const std::string& path) {
  Trajectory t;
  std::string error;
  EXPECT_TRUE(ReadTrajectory(path, TrajectoryFormat::TUM, &t, &error)) << error;
  return t;
}

TEST(MlndtLocalizeTimes, TumStampsAreTheScanTimesOrSayTheyAreIndices) {
  const std::string dir = testing::FreshTestDir("mlndt_localize_times");
  const std::string chain = Chain(dir);
  const ToolRun map =
      RunTool("mlndt_map",
              "--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(chain) +
                  kMapFlags + " --output=" + Quote(dir + "/map.mlndt"));
  ASSERT_EQ(map.exit_code, 0) << map.err;
  {
    std::ofstream times(dir + "/times.txt");
    for (int k = 0; k < 8; ++k) times << 50.0 + 0.1 * k << "\n";
  }
  const std::string common =
      "--map=" + Quote(dir + "/map.mlndt") + " --scans=" + Quote(KittiPcd()) +
      " --max_scans=3 --initial_poses=" + Quote(chain) + " --plots=false";
  const ToolRun timed =
      RunTool("mlndt_localize",
              common + " --times=" + Quote(dir + "/times.txt") +
                  " --output_dir=" + Quote(dir + "/timed"));
  const ToolRun untimed = RunTool(
      "mlndt_localize", common + " --output_dir=" + Quote(dir + "/untimed"));
  ASSERT_EQ(timed.exit_code, 0) << timed.err;
  ASSERT_EQ(untimed.exit_code, 0) << untimed.err;
  const Trajectory t = ReadTum(dir + "/timed/trajectory_tum.txt");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t.timestamp_s(0), 50.0, 1e-12);
  EXPECT_NEAR(t.timestamp_s(2), 50.2, 1e-12);
  EXPECT_FALSE(TumStampsAreScanIndices(dir + "/timed/trajectory_tum.txt"));
  EXPECT_TRUE(TumStampsAreScanIndices(dir + "/untimed/trajectory_tum.txt"));
  // A times file with a stamp per scan or none at all.
  std::ofstream(dir + "/short.txt") << "1\n2\n";
  const ToolRun short_times =
      RunTool("mlndt_localize",
              common + " --times=" + Quote(dir + "/short.txt") +
                  " --output_dir=" + Quote(dir + "/short"));
  EXPECT_EQ(short_times.exit_code, 2);
  EXPECT_NE(short_times.err.find("has 2 stamps for 8 scans"), std::string::npos)
      << short_times.err;
}

TEST(MlndtLocalizeTimes, MapAndLocalizeReadABagAsTheFolder) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("mlndt_localize_times");
  const std::string chain = Chain(dir);
  std::vector<std::string> scans;
  for (int i = 0; i < 8; ++i) {
    scans.push_back(KittiPcd() + "/00000" + std::to_string(i) + ".pcd");
  }
  std::string error;
  ASSERT_TRUE(
      testing::WriteTestBag(dir + "/k.bag", "/points", scans, "", &error))
      << error;
  const ToolRun folder =
      RunTool("mlndt_map",
              "--scans=" + Quote(KittiPcd()) + " --poses=" + Quote(chain) +
                  kMapFlags + " --output=" + Quote(dir + "/folder.mlndt"));
  const ToolRun bag =
      RunTool("mlndt_map",
              "--bag=" + Quote(dir + "/k.bag") + " --topic=/points" +
                  " --poses=" + Quote(chain) + kMapFlags +
                  " --output=" + Quote(dir + "/bag.mlndt"));
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  ASSERT_EQ(bag.exit_code, 0) << bag.err;
  EXPECT_EQ(ReadWholeFile(dir + "/bag.mlndt"),
            ReadWholeFile(dir + "/folder.mlndt"));
  const ToolRun localize = RunTool(
      "mlndt_localize",
      "--map=" + Quote(dir + "/bag.mlndt") + " --bag=" + Quote(dir + "/k.bag") +
          " --topic=/points --max_scans=2 --initial_poses=" + Quote(chain) +
          " --plots=false --output_dir=" + Quote(dir + "/out"));
  ASSERT_EQ(localize.exit_code, 0) << localize.err;
  const Trajectory t = ReadTum(dir + "/out/trajectory_tum.txt");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t.timestamp_s(1), 1000.1, 1e-6);
}

}  // namespace
}  // namespace mlndt
