// Runs the built mlndt_pairs binary: flags refused before any scan is read,
// with exit 2 and a message naming the flag.

#include <gtest/gtest.h>

#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

TEST(MlndtPairs, RefusesGapsThatAreNotWholeFramesOfAtLeastOne) {
  const std::string base =
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
      " --gt_poses=" + Quote(testing::BundledDataPath("kitti/poses_velo.txt"));
  struct Case {
    std::string gaps;
    std::string message;
  } cases[] = {
      {"0", "--gaps=0: a gap is a whole number of frames >= 1"},
      {"1,0", "--gaps=1,0: a gap is a whole number of frames >= 1"},
      {"-1", "--gaps=-1: a gap is a whole number of frames >= 1"},
      {"1.5", "--gaps=1.5: a gap is a whole number of frames >= 1"},
      {"1,,2", "--gaps=1,,2: expected comma-separated frame gaps"},
  };
  for (const Case& c : cases) {
    const ToolRun run =
        testing::RunTool("mlndt_pairs", base + " --gaps=" + Quote(c.gaps));
    EXPECT_EQ(run.exit_code, 2) << c.gaps << "\nstderr: " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.gaps << "\nstderr: " << run.err;
    EXPECT_TRUE(run.lines.empty()) << c.gaps << ": " << run.out;
  }
}

TEST(MlndtPairs, RefusesAStartLayerBeyondTheMap) {
  const ToolRun run = testing::RunTool(
      "mlndt_pairs",
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
          " --gt_poses=" +
          Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
          " --finest_cell_size=0 --num_layers=2 --start_layer=3");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--start_layer=3 is out of range"), std::string::npos)
      << run.err;
  EXPECT_TRUE(run.lines.empty()) << run.out;
}

}  // namespace
}  // namespace mlndt
