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

TEST(MlndtPairs, RefusesGapsThatAreNotWholeFramesInRange) {
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
      // Out of range: refused, not wrapped or rounded to 0 (every scan
      // onto itself) or left without a pair (8 scans).
      {"1e300", "--gaps=1e300: a gap is a whole number of frames >= 1"},
      {"18446744073709551615",
       "'18446744073709551615' is not a whole number in [1, 7]"},
      {"18446744073709551616",
       "'18446744073709551616' is not a whole number in [1, 7]"},
      {"8", "below the number of scans (8): '8' is not"},
      {"+1", "'+1' is not"},
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
          " --finest_cell_size_m=0 --num_layers=2 --start_layer=3");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--start_layer=3 is out of range"), std::string::npos)
      << run.err;
  EXPECT_TRUE(run.lines.empty()) << run.out;
}

// KITTI camera poses need --poses_are_camera with --calib, as in every tool
// that reads pose files (pose_flags.h); with both they match the Velodyne
// poses.
TEST(MlndtPairs, CameraPosesNeedCalibAndThenMatchVelodynePoses) {
  const std::string scans =
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
      " --gaps=7 --perturbations=";
  const std::string camera =
      " --gt_poses=" + Quote(testing::BundledDataPath("kitti/poses_cam0.txt"));
  const ToolRun refused =
      testing::RunTool("mlndt_pairs", scans + camera + " --poses_are_camera");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("--poses_are_camera needs --calib"),
            std::string::npos)
      << refused.err;

  const ToolRun converted =
      testing::RunTool("mlndt_pairs",
                       scans + camera + " --poses_are_camera --calib=" +
                           Quote(testing::BundledDataPath("kitti/calib.txt")));
  const ToolRun velodyne = testing::RunTool(
      "mlndt_pairs",
      scans + " --gt_poses=" +
          Quote(testing::BundledDataPath("kitti/poses_velo.txt")));
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  ASSERT_EQ(velodyne.exit_code, 0) << velodyne.err;
  // The one pair (7 onto 0) has the same error line (the same truth).
  ASSERT_GE(converted.lines.size(), 2u);
  ASSERT_GE(velodyne.lines.size(), 2u);
  EXPECT_EQ(converted.lines[1].substr(0, 60), velodyne.lines[1].substr(0, 60));
  // The one run counted by verdict (issue 27): five keys, summing to 1.
  EXPECT_NE(velodyne.out.find("verdicts: CONVERGENCE 1, NO_CONVERGENCE 0, "
                              "LOW_QUALITY 0, DEGENERATE 0, FAILURE 0"),
            std::string::npos)
      << velodyne.out;
}

}  // namespace
}  // namespace mlndt
