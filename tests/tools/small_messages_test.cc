// Messages that say what happened (issue 41 item 14): mlndt_odometry's RPE
// line names the scans it used on a run shorter than --rpe_delta; a map
// over a cloud with a stray point at 1e30 m names that point; GBS sampling
// that keeps no point at --gbs_cell_size_m=0.001 says why.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

TEST(SmallMessages, OdometryRpeNamesTheScansItUsed) {
  const std::string out = testing::FreshTestDir("small_messages") + "/out";
  const ToolRun run =
      RunTool("mlndt_odometry",
              "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
                  " --gt_poses=" +
                  Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
                  " --plots=false --output_dir=" + Quote(out),
              300);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.find("RPE over 100 scans"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("RPE over 7 scans (--rpe_delta=100 is longer than "
                         "the run)"),
            std::string::npos)
      << run.out;
  EXPECT_NE(testing::ReadWholeFile(out + "/summary.json")
                .find("\"rpe_delta_scans\": 7"),
            std::string::npos);
}

TEST(SmallMessages, FarPointOfAMapIsNamed) {
  const std::string dir = testing::FreshTestDir("small_messages");
  const std::string cloud = dir + "/cloud.xyz";
  {
    std::ofstream out(cloud);
    for (int i = 0; i < 20; ++i) {
      for (int j = 0; j < 20; ++j) {
        out << i * 0.5 << " " << j * 0.5 << " " << (i + j) % 3 * 0.2 << "\n";
      }
    }
    out << "1e30 2 3\n";  // Index 400.
  }
  const ToolRun run = RunTool(
      "mlndt_map",
      "--cloud=" + Quote(cloud) + " --output=" + Quote(dir + "/map.mlndtmap"));
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.err.find("index 400, is at (1e+30, 2, 3)"), std::string::npos)
      << run.err;
}

TEST(SmallMessages, GbsCellTooSmallForAnyPointSaysWhy) {
  const ToolRun run = RunTool("mlndt_align", "--gbs_cell_size_m=0.001");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("sampling kept no input points: all"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("fewer than gbs_min_points_per_cell = 3 points"),
            std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace mlndt
