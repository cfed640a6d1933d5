// The data as a user types it (tools/cli/data_argument.h): `mlndt_odometry
// DIR_OR_BAG` without --output_dir writes what --scans/--bag with an output
// folder writes, into a new folder named on stderr; a bag's one PointCloud2
// topic needs no --topic.

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

// Runs `tool` with `args` from the folder `cwd`.
ToolRun RunFrom(const std::string& cwd,
                const std::string& tool,
                const std::string& args) {
  const fs::path before = fs::current_path();
  fs::current_path(cwd);
  ToolRun run = RunTool(tool, args);
  fs::current_path(before);
  return run;
}

// The one folder in `dir` whose name starts with `prefix`, or "".
std::string OnlyFolderStartingWith(const std::string& dir,
                                   const std::string& prefix) {
  std::string found;
  int count = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.rfind(prefix, 0) == 0) {
      found = entry.path().string();
      ++count;
    }
  }
  return count == 1 ? found : "";
}

TEST(DataArgument, FolderArgumentWritesTheFlagsRunIntoANewFolder) {
  const std::string dir = testing::FreshTestDir("data_argument");
  const std::string pcd = testing::BundledDataPath("kitti/pcd");
  const ToolRun flags =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(pcd) + " --max_scans=3 --plots=false" +
                  " --output_dir=" + Quote(dir + "/flags"));
  ASSERT_EQ(flags.exit_code, 0) << flags.err;
  fs::create_directories(dir + "/cwd");
  const ToolRun argument = RunFrom(dir + "/cwd",
                                   "mlndt_odometry",
                                   Quote(pcd) + " --max_scans=3 --plots=false");
  ASSERT_EQ(argument.exit_code, 0) << argument.err;
  const std::string out =
      OnlyFolderStartingWith(dir + "/cwd", "mlndt_odometry_");
  ASSERT_FALSE(out.empty()) << argument.err;
  EXPECT_NE(argument.err.find("--output_dir=mlndt_odometry_"),
            std::string::npos)
      << argument.err;
  const std::string trajectory =
      ReadWholeFile(dir + "/flags/trajectory_kitti.txt");
  EXPECT_FALSE(trajectory.empty());
  EXPECT_EQ(ReadWholeFile(out + "/trajectory_kitti.txt"), trajectory);
}

TEST(DataArgument, RefusesAMissingPathAndTheDataGivenTwice) {
  const std::string dir = testing::FreshTestDir("data_argument_refused");
  const ToolRun missing = RunFrom(
      dir, "mlndt_sequence", Quote(dir + "/nothing") + " --plots=false");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("is neither a folder of scans nor a bag file"),
            std::string::npos)
      << missing.err;
  const std::string pcd = testing::BundledDataPath("kitti/pcd");
  const ToolRun twice =
      RunFrom(dir, "mlndt_odometry", Quote(pcd) + " --scans=" + Quote(pcd));
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("as an argument and as --scans or --bag"),
            std::string::npos)
      << twice.err;
  EXPECT_TRUE(fs::is_empty(dir)) << "a refused run wrote into " << dir;
}

TEST(DataArgument, BagArgumentReadsItsOnePointCloudTopic) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("data_argument_bag");
  const std::string pcd = testing::BundledDataPath("kitti/pcd");
  std::vector<std::string> scans;
  for (int i = 0; i < 3; ++i) {
    scans.push_back(pcd + "/00000" + std::to_string(i) + ".pcd");
  }
  std::string error;
  ASSERT_TRUE(testing::WriteTestBag(
      dir + "/k.bag", "/points", scans, "--other_topic=/status", &error))
      << error;
  const ToolRun named =
      RunTool("mlndt_odometry",
              "--bag=" + Quote(dir + "/k.bag") + " --topic=/points" +
                  " --plots=false --output_dir=" + Quote(dir + "/named"));
  ASSERT_EQ(named.exit_code, 0) << named.err;
  fs::create_directories(dir + "/cwd");
  const ToolRun guessed = RunFrom(
      dir + "/cwd", "mlndt_odometry", Quote(dir + "/k.bag") + " --plots=false");
  ASSERT_EQ(guessed.exit_code, 0) << guessed.err;
  const std::string out =
      OnlyFolderStartingWith(dir + "/cwd", "mlndt_odometry_");
  ASSERT_FALSE(out.empty()) << guessed.err;
  EXPECT_EQ(ReadWholeFile(out + "/trajectory_tum.txt"),
            ReadWholeFile(dir + "/named/trajectory_tum.txt"));
  EXPECT_NE(ReadWholeFile(out + "/trajectory_tum.txt").find("/points"),
            std::string::npos);
}

}  // namespace
}  // namespace mlndt
