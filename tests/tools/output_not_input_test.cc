// Outputs never overwrite inputs (issue 41 item 10): a pose or times file
// that sits at one of the run's output paths, or `mlndt_eval chain X X`,
// is refused before any work (exit 2) and left as it was; a symbolic link
// at an output path is refused before the run, not after it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

// Copies `from` to `to` (creating its folder) and returns its text.
std::string Copy(const std::string& from, const std::string& to) {
  fs::create_directories(fs::path(to).parent_path());
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  return ReadWholeFile(to);
}

TEST(OutputNotInput, PoseAndTimesFilesAtOutputPathsAreRefused) {
  const std::string dir = testing::FreshTestDir("output_not_input");
  const std::string scans =
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd"));
  const std::string poses = testing::BundledDataPath("kitti/poses_velo.txt");
  struct Case {
    const char* tool;
    const char* file;  // In the output folder, holding the input.
    const char* flag;  // Given the file.
  } cases[] = {
      {"mlndt_sequence", "trajectory_kitti.txt", "gt_poses"},
      {"mlndt_sequence", "trajectory_tum.txt", "gt_poses"},
      {"mlndt_sequence", "gt_trajectory_kitti.txt", "gt_poses"},
      {"mlndt_odometry", "trajectory_kitti.txt", "gt_poses"},
      {"mlndt_odometry", "trajectory_tum.txt", "gt_poses"},
  };
  int k = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.tool) + " " + c.file);
    const std::string out = dir + "/out" + std::to_string(k++);
    const std::string input = out + "/" + c.file;
    const std::string text = Copy(poses, input);
    const ToolRun run = RunTool(c.tool,
                                scans + " --" + c.flag + "=" + Quote(input) +
                                    " --plots=false --output_dir=" + Quote(out),
                                120);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(c.file), std::string::npos) << run.err;
    EXPECT_EQ(ReadWholeFile(input), text);
    EXPECT_FALSE(fs::exists(out + "/summary.json"));
  }
  // --times at the odometry's TUM output.
  const std::string out = dir + "/times";
  const std::string times = out + "/trajectory_tum.txt";
  fs::create_directories(out);
  std::ofstream(times) << "0\n0.1\n0.2\n0.3\n0.4\n0.5\n0.6\n0.7\n";
  const ToolRun run = RunTool("mlndt_odometry",
                              scans + " --times=" + Quote(times) +
                                  " --plots=false --output_dir=" + Quote(out),
                              120);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(ReadWholeFile(times), "0\n0.1\n0.2\n0.3\n0.4\n0.5\n0.6\n0.7\n");
  EXPECT_FALSE(fs::exists(out + "/summary.json"));
}

TEST(OutputNotInput, SymbolicLinkAtATrajectoryPathIsRefusedBeforeTheRun) {
  const std::string dir = testing::FreshTestDir("output_not_input");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  fs::create_symlink(dir + "/elsewhere.txt", out + "/trajectory_tum.txt");
  const ToolRun run =
      RunTool("mlndt_sequence",
              "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) +
                  " --plots=false --output_dir=" + Quote(out),
              120);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("trajectory_tum.txt"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out + "/pairs.csv"));
}

TEST(OutputNotInput, EvalChainRefusesToWriteOverItsPairsFile) {
  const std::string dir = testing::FreshTestDir("output_not_input");
  const std::string pairs = dir + "/pairs.json";
  const std::string text =
      Copy(testing::BundledDataPath("kitti/reference_pairs.json"), pairs);
  fs::create_symlink(pairs, dir + "/link.json");
  for (const std::string& output : {pairs, dir + "/link.json"}) {
    const ToolRun run =
        RunTool("mlndt_eval", "chain " + Quote(pairs) + " " + Quote(output));
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("is the pairs file"), std::string::npos) << run.err;
    EXPECT_EQ(ReadWholeFile(pairs), text);
  }
}

}  // namespace
}  // namespace mlndt
