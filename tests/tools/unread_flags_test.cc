// No flag silently ignored, and one exit code per refusal (issue 41 item
// 13): mlndt_align and mlndt_eval refuse the scan and pose flags of the
// shared code they link (--bag, --topic, --times, --calib,
// --poses_are_camera) with exit 2 and leave them out of --help;
// mlndt_map --help does not list --times, which it refuses; an output
// format no tool can write is refused with exit 2 before any work by
// mlndt_convert as by mlndt_align --output_cloud.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

const char* const kUnreadFlags[] = {"--bag=run.bag",
                                    "--topic=/points",
                                    "--times=times.txt",
                                    "--calib=calib.txt",
                                    "--poses_are_camera"};

// "--bag" for "--bag=run.bag".
std::string FlagName(const std::string& flag) {
  return flag.substr(0, flag.find('='));
}

void ExpectRefused(const std::string& tool, const std::string& args) {
  for (const char* flag : kUnreadFlags) {
    SCOPED_TRACE(tool + " " + flag);
    const ToolRun run = RunTool(tool, args + " " + flag, 120);
    EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
    EXPECT_NE(run.err.find(FlagName(flag) + " does not apply to " + tool),
              std::string::npos)
        << run.err;
    EXPECT_EQ(run.out, "");
  }
  const ToolRun help = RunTool(tool, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : kUnreadFlags) {
    EXPECT_EQ(help.out.find("  " + FlagName(flag) + "="), std::string::npos)
        << tool << " --help lists " << FlagName(flag);
  }
}

TEST(UnreadFlags, AlignRefusesScanAndPoseFlags) {
  // The bundled pair (no arguments) registers and exits 0 without them.
  ExpectRefused("mlndt_align", "");
}

TEST(UnreadFlags, EvalRefusesScanAndPoseFlags) {
  const std::string poses =
      Quote(testing::BundledDataPath("kitti/poses_velo.txt"));
  ExpectRefused("mlndt_eval", "--reference=" + poses + " --estimate=" + poses);
}

TEST(UnreadFlags, MapHelpDoesNotListTimes) {
  const ToolRun help = RunTool("mlndt_map", "--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_EQ(help.out.find("  --times="), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("  --bag="), std::string::npos) << help.out;
  const ToolRun run = RunTool(
      "mlndt_map",
      "--scans=" + Quote(testing::BundledDataPath("kitti/pcd")) + " --poses=" +
          Quote(testing::BundledDataPath("kitti/poses_velo.txt")) +
          " --times=times.txt --output=/nonexistent/m.mlndtmap");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--times"), std::string::npos) << run.err;
}

TEST(UnreadFlags, UnwritableCloudFormatIsTheSameRefusalEverywhere) {
  const std::string dir = testing::FreshTestDir("unread_flags");
  const std::string pcd = dir + "/in.pcd";
  const ToolRun make =
      RunTool("mlndt_convert",
              Quote(testing::BundledDataPath("koide3/251370668.pcd")) + " " +
                  Quote(pcd));
  ASSERT_EQ(make.exit_code, 0) << make.err;
  const ToolRun convert =
      RunTool("mlndt_convert", Quote(pcd) + " " + Quote(dir + "/out.bin"));
  EXPECT_EQ(convert.exit_code, 2) << convert.err;
  EXPECT_NE(convert.err.find("out.bin"), std::string::npos) << convert.err;
  EXPECT_FALSE(fs::exists(dir + "/out.bin"));
  const ToolRun align =
      RunTool("mlndt_align", "--output_cloud=" + Quote(dir + "/out.bin"));
  EXPECT_EQ(align.exit_code, convert.exit_code) << align.err;
  EXPECT_FALSE(fs::exists(dir + "/out.bin"));
}

}  // namespace
}  // namespace mlndt
