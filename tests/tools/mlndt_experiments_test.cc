// Runs the built mlndt_experiments binary on the bundled KITTI frames with
// options that keep it to a few seconds, and checks REPORT.md, the figures
// and the exit codes.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
const auto& ReadFile = testing::ReadWholeFile;

namespace fs = std::filesystem;

std::string TestDir(const std::string& suffix = "") {
  const std::string dir =
      ::testing::TempDir() + "mlndt_experiments_test_" +
      ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ToolRun RunExperiments(const std::string& args) {
  return testing::RunTool("mlndt_experiments", args);
}

bool GnuplotInstalled() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

// Few scans, offsets, fractions and seeds, and the fast LM backend.
const char kTinyRun[] =
    " --max_scans=3 --steps=1 --table9_steps=1,2 --translation_offsets=0,10"
    " --rotation_offsets=0,15 --long_range_ndt_cells=0 --fractions=0,0.9 "
    "--random_seeds=1"
    " --adaptive_inits=constant_velocity --backend=lm";

TEST(MlndtExperiments, TinyRunWritesEveryReportSection) {
  const std::string dir = TestDir();
  const bool plots = GnuplotInstalled();
  const ToolRun run = RunExperiments("--output_dir=" + Quote(dir) + kTinyRun +
                                     (plots ? "" : " --plots=false"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const std::string report = ReadFile(dir + "/REPORT.md");
  ASSERT_FALSE(report.empty());
  // The command line comes first, then the data caveat and every section.
  EXPECT_EQ(report.find("# ML-NDT experiments"), 0u);
  EXPECT_NE(
      report.find("Command:\n\n```\n" + testing::ToolPath("mlndt_experiments")),
      std::string::npos);
  EXPECT_NE(report.find("--max_scans=3"), std::string::npos);
  for (const char* section :
       {"**Ground-truth caveat**",
        "## 1. Long-range convergence (Section 5.1)",
        "## 2. Optimisers: score against iteration (Figs. 11 and 13)",
        "## 3. Accuracy and sampling strategies (Tables 2–8)",
        "## 4. Start layer × initialisation (Table 9)",
        "## 5. Adaptive start layer (end of Section 5.3)",
        "## Notes"}) {
    EXPECT_NE(report.find(section), std::string::npos) << section;
  }
  // Tables with the paper's numbers beside ours.
  for (const char* text : {"| offset [m] |",
                           "| offset [deg] |",
                           "paper's claim",
                           "| ML-NDT Newton |",
                           "| ML-NDT LM |",
                           "| ML-NDT Ceres |",
                           "| ML-NDT, GBS |",
                           "| NDT, random |",
                           "paper Table 4",
                           "| c = Z_i/Z_gt |",
                           "| 0.9 | 1 (",
                           "| 45 % | 14.00 | 4.31 |",
                           "**adaptive**"}) {
    EXPECT_NE(report.find(text), std::string::npos) << text;
  }
  if (plots) {
    for (const char* png : {"long_range_translation.png",
                            "long_range_rotation.png",
                            "optimizers_identity.png",
                            "optimizers_offset.png",
                            "sampling.png",
                            "table9.png"}) {
      EXPECT_GT(fs::file_size(dir + "/" + png), 1000u) << png;
      EXPECT_NE(report.find(std::string("(") + png + ")"), std::string::npos)
          << png;
    }
  }
  EXPECT_NE(run.out.find("REPORT.md"), std::string::npos) << run.out;
}

TEST(MlndtExperiments, SelectedExperimentsOnly) {
  const std::string dir = TestDir();
  const ToolRun run = RunExperiments("--output_dir=" + Quote(dir) + kTinyRun +
                                     " --experiments=optimizers --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string report = ReadFile(dir + "/REPORT.md");
  EXPECT_NE(report.find("## 2. Optimisers"), std::string::npos);
  EXPECT_EQ(report.find("## 1. Long-range"), std::string::npos);
  EXPECT_EQ(report.find("## 4. Start layer"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/optimizers_identity.png"));
}

TEST(MlndtExperiments, ReadsTheSharedDataLayout) {
  MLNDT_REQUIRE_SHARED_DATA(shared);
  if (!fs::is_directory(shared + "/kitti00_frames_0000_0007")) {
    GTEST_SKIP() << shared << " has no kitti00_frames_0000_0007/";
  }
  const std::string dir = TestDir();
  const ToolRun run = RunExperiments("--data_dir=" + Quote(shared) +
                                     " --output_dir=" + Quote(dir) + kTinyRun +
                                     " --experiments=optimizers --plots=false");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(ReadFile(dir + "/REPORT.md").find("kitti00_frames_0000_0007/pcd"),
            std::string::npos);
}

TEST(MlndtExperiments, BadFlagsExitOne) {
  const std::string dir = TestDir();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "Usage"},
      {"--output_dir=" + Quote(dir) + " --experiments=bogus", "bogus"},
      {"--output_dir=" + Quote(dir) + " --steps=0", "--steps"},
      {"--output_dir=" + Quote(dir) + " --data_dir=/nonexistent",
       "/nonexistent"},
      {"--output_dir=" + Quote(dir) + " --method=bogus", "--method"},
      {"--output_dir=" + Quote(dir) + " --experiments=table9 --fractions=x",
       "--fractions"},
      {"--output_dir=" + Quote(dir) +
           " --experiments=optimizers --optimizer_pair=99",
       "optimizer_pair"},
  };
  for (const auto& [args, message] : cases) {
    const ToolRun run = RunExperiments(args);
    EXPECT_EQ(run.exit_code, 1) << args << "\n" << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << args << "\n"
                                                        << run.err;
  }
}

TEST(MlndtExperiments, MissingGnuplotExitsOneButWritesTheReport) {
  const std::string dir = TestDir();
  const ToolRun run = RunExperiments(
      "--output_dir=" + Quote(dir) + kTinyRun +
      " --experiments=optimizers --gnuplot=/nonexistent/gnuplot");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("gnuplot"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_regular_file(dir + "/REPORT.md"));
}

}  // namespace
}  // namespace mlndt
