// An output set a reader can tell a finished run by (issue 41 item 12):
// mlndt_odometry, mlndt_sequence and mlndt_localize remove the previous
// summary.json before they write anything and write it last, naming every file
// they wrote with its size; render folders (.mlndt_plot.*) that a killed run
// left behind are removed by the next plot in that folder.

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

std::string Scans() {
  return "--scans=" + Quote(testing::BundledDataPath("kitti/pcd"));
}

// summary.json names each file of `names` with its size, and was written
// after every one of them.
void ExpectSummaryLastAndNaming(const std::string& dir,
                                const std::vector<std::string>& names) {
  const std::string summary = ReadWholeFile(dir + "/summary.json");
  ASSERT_NE(summary.find("\"output_files\""), std::string::npos) << summary;
  const auto summary_time = fs::last_write_time(dir + "/summary.json");
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const std::string entry = "\"name\": \"" + name + "\",\n      \"bytes\": " +
                              std::to_string(fs::file_size(dir + "/" + name));
    EXPECT_NE(summary.find(entry), std::string::npos) << summary;
    EXPECT_LE(fs::last_write_time(dir + "/" + name), summary_time);
  }
}

TEST(OutputSet, OdometrySummaryIsWrittenLastAndNamesItsFiles) {
  const std::string out = testing::FreshTestDir("output_set") + "/out";
  const ToolRun run =
      RunTool("mlndt_odometry", Scans() + " --output_dir=" + Quote(out), 300);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ExpectSummaryLastAndNaming(out,
                             {"scans.csv",
                              "scans.json",
                              "trajectory_kitti.txt",
                              "trajectory_tum.txt",
                              "trajectory_xy.png"});
}

TEST(OutputSet, SequenceSummaryIsWrittenLastAndNamesItsFiles) {
  const std::string out = testing::FreshTestDir("output_set") + "/out";
  const ToolRun run =
      RunTool("mlndt_sequence",
              Scans() + " --plots=false --gt_poses=" +
                  Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
                  " --output_dir=" + Quote(out),
              300);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ExpectSummaryLastAndNaming(out,
                             {"pairs.csv",
                              "trace.csv",
                              "trajectory_kitti.txt",
                              "trajectory_tum.txt",
                              "gt_trajectory_kitti.txt"});
}

TEST(OutputSet, LocalizeSummaryIsWrittenLastAndNamesItsFiles) {
  const std::string dir = testing::FreshTestDir("output_set");
  const std::string map = dir + "/kitti.mlndt";
  const ToolRun built =
      RunTool("mlndt_map",
              Scans() + " --poses=" +
                  Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
                  " --max_scans=2 --voxel_size=0.2 --output=" + Quote(map));
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string out = dir + "/out";
  const ToolRun run = RunTool("mlndt_localize",
                              "--map=" + Quote(map) + " " + Scans() +
                                  " --max_scans=2 --output_dir=" + Quote(out),
                              300);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ExpectSummaryLastAndNaming(out,
                             {"trajectory_kitti.txt",
                              "trajectory_tum.txt",
                              "scans.csv",
                              "trajectory_xy.png"});
}

// A run that stops after its work began leaves no summary.json of an
// earlier run beside its own files.
TEST(OutputSet, AFailedRunLeavesNoEarlierSummary) {
  const std::string dir = testing::FreshTestDir("output_set");
  const std::string scans = dir + "/scans";
  fs::create_directories(scans);
  for (const char* name : {"000000.pcd", "000001.pcd", "000002.pcd"}) {
    fs::copy_file(testing::BundledDataPath(std::string("kitti/pcd/") + name),
                  scans + "/" + name);
  }
  std::ofstream(scans + "/000003.pcd") << "not a point cloud\n";
  for (const char* tool : {"mlndt_odometry", "mlndt_sequence"}) {
    SCOPED_TRACE(tool);
    const std::string out = dir + "/out_" + tool;
    fs::create_directories(out);
    std::ofstream(out + "/summary.json") << "{\"earlier\": true}\n";
    const ToolRun run = RunTool(
        tool,
        "--scans=" + Quote(scans) + " --plots=false --output_dir=" + Quote(out),
        300);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_FALSE(fs::exists(out + "/summary.json"));
  }
}

TEST(OutputSet, StaleRenderFoldersAreRemoved) {
  const std::string out = testing::FreshTestDir("output_set") + "/out";
  fs::create_directories(out);
  // Of a process that is gone (above any pid_max), of an older version
  // (no pid) two hours old, and of a running process (this test).
  const std::string dead = out + "/.mlndt_plot.999999999.AbCdEf";
  const std::string old = out + "/.mlndt_plot.GhIjKl";
  const std::string live =
      out + "/.mlndt_plot." + std::to_string(::getpid()) + ".MnOpQr";
  for (const std::string& folder : {dead, old, live}) {
    fs::create_directories(folder);
    std::ofstream(folder + "/trajectory_xy.png") << "half a figure";
  }
  fs::last_write_time(old,
                      fs::file_time_type::clock::now() - std::chrono::hours(2));
  const ToolRun run =
      RunTool("mlndt_odometry", Scans() + " --output_dir=" + Quote(out), 300);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_FALSE(fs::exists(old));
  EXPECT_TRUE(fs::exists(live));
}

}  // namespace
}  // namespace mlndt
