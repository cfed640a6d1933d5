// Pose k belongs to scan k: mlndt_sequence, mlndt_odometry, mlndt_posegraph
// and mlndt_pairs refuse a pose file whose count is not the scans' (a
// missing scan, or a file of a longer run) before any work, exit 2, as
// mlndt_map does; every later pose would be off by one.

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

// The bundled KITTI frames 0-7 but frame `missing`, in `dir`.
void CopyFramesBut(int missing, const std::string& dir) {
  fs::create_directories(dir);
  for (int k = 0; k < 8; ++k) {
    if (k == missing) continue;
    const std::string name = "00000" + std::to_string(k) + ".pcd";
    fs::copy_file(testing::BundledDataPath("kitti/pcd/" + name),
                  dir + "/" + name);
  }
}

TEST(PoseCount, ToolsRefuseMorePosesThanScansBeforeAnyWork) {
  const std::string dir = testing::FreshTestDir("pose_count");
  const std::string scans = dir + "/scans";
  CopyFramesBut(3, scans);  // 7 scans.
  const std::string poses = testing::BundledDataPath("kitti/poses_velo.txt");
  const std::string out = dir + "/out";
  const std::string s = "--scans=" + Quote(scans);
  const std::string gt = " --gt_poses=" + Quote(poses);
  const std::string o = " --plots=false --output_dir=" + Quote(out);
  struct Case {
    const char* tool;
    std::string args;
    const char* flag;
  } cases[] = {
      {"mlndt_sequence", s + gt + o, "--gt_poses="},
      {"mlndt_sequence", s + " --init=poses:" + Quote(poses) + o, "--init="},
      {"mlndt_odometry", s + gt + o, "--gt_poses="},
      {"mlndt_posegraph", s + gt, "--gt_poses="},
      {"mlndt_posegraph",
       s + " --init=odometry --odometry_poses=" + Quote(poses),
       "--odometry_poses="},
      {"mlndt_pairs", s + gt, "--gt_poses="},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.tool) + " " + c.args);
    const ToolRun run = RunTool(c.tool, c.args, 120);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(c.flag), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("has 8 poses for 7 scans (pose k belongs to scan k"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(run.lines.empty()) << run.out;
    EXPECT_FALSE(fs::exists(out));
  }
}

// --max_scans takes the first scans of a longer run: more poses are then
// right.
TEST(PoseCount, MaxScansTakesTheFirstScansOfALongerRun) {
  const std::string dir = testing::FreshTestDir("pose_count");
  const ToolRun run = RunTool(
      "mlndt_sequence",
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
          " --gt_poses=" +
          Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
          " --max_scans=2 --plots=false --output_dir=" + Quote(dir + "/out"),
      300);
  EXPECT_NE(run.exit_code, 2) << run.err;
  EXPECT_TRUE(fs::exists(dir + "/out/pairs.csv"));
}

}  // namespace
}  // namespace mlndt
