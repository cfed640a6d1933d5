// The scan folder holds the inputs only (issue 41 item 11): --output_dir
// equal to the scan folder is refused before any work (a later run would
// read the trajectories as scans), and the .txt files kept beside the
// scans (stamps.txt, KITTI's calib.txt) are not read as clouds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

// A copy of the bundled KITTI scans in `dir`/scans; returns the folder.
std::string CopyKittiScans(const std::string& dir) {
  const std::string scans = dir + "/scans";
  fs::create_directories(scans);
  for (const auto& entry :
       fs::directory_iterator(testing::BundledDataPath("kitti/pcd"))) {
    fs::copy_file(entry.path(), scans + "/" + entry.path().filename().string());
  }
  return scans;
}

TEST(ScanFolder, OutputDirEqualToTheScanFolderIsRefused) {
  const std::string dir = testing::FreshTestDir("scan_folder");
  const std::string scans = CopyKittiScans(dir);
  const std::string poses =
      Quote(testing::BundledDataPath("kitti/poses_velo.txt"));
  struct Case {
    const char* tool;
    std::string args;
  } cases[] = {
      {"mlndt_sequence", "--gt_poses=" + poses + " --plots=false"},
      {"mlndt_odometry", "--plots=false"},
      {"mlndt_posegraph", "--gt_poses=" + poses},
  };
  for (const Case& c : cases) {
    for (const std::string& out : {scans, scans + "/", scans + "/."}) {
      SCOPED_TRACE(std::string(c.tool) + " " + out);
      const ToolRun run = RunTool(c.tool,
                                  "--scans=" + Quote(scans) + " " + c.args +
                                      " --output_dir=" + Quote(out),
                                  120);
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_NE(run.err.find("--output_dir"), std::string::npos) << run.err;
      EXPECT_NE(run.err.find("folder this run reads"), std::string::npos)
          << run.err;
      EXPECT_FALSE(fs::exists(scans + "/summary.json"));
    }
  }
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(scans)) {
    EXPECT_EQ(entry.path().extension(), ".pcd") << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 8u);
}

TEST(ScanFolder, StampsAndCalibrationBesideTheScansAreNotScans) {
  const std::string dir = testing::FreshTestDir("scan_folder");
  const std::string scans = CopyKittiScans(dir);
  fs::copy_file(testing::BundledDataPath("kitti/calib.txt"),
                scans + "/calib.txt");
  std::ofstream(scans + "/stamps.txt")
      << "0\n0.1\n0.2\n0.3\n0.4\n0.5\n0.6\n0.7\n";
  const std::string out = dir + "/out";
  const ToolRun run = RunTool("mlndt_odometry",
                              "--scans=" + Quote(scans) +
                                  " --times=" + Quote(scans + "/stamps.txt") +
                                  " --plots=false --output_dir=" + Quote(out),
                              300);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err.find("calib.txt"), std::string::npos) << run.err;
  std::ifstream trajectory(out + "/trajectory_tum.txt");
  std::string line;
  int poses = 0;
  while (std::getline(trajectory, line)) {
    if (!line.empty() && line[0] != '#') ++poses;
  }
  EXPECT_EQ(poses, 8);
}

}  // namespace
}  // namespace mlndt
