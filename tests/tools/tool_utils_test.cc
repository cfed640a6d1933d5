// The tools' shared helpers (tools/cli/tool_utils.h): number lists from
// flags and atomic output files, with end-to-end checks on mlndt_align: a
// malformed list, a full disk and a symbolic link as --output_json are clear
// errors with exit code 1, and an earlier output survives them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/small_file_system.h"
#include "tests/testing/test_data.h"
#include "tools/cli/list_flags.h"

namespace mlndt {
namespace {

TEST(ParseNumberList, CommaSeparatedNumbers) {
  std::vector<double> values;
  ASSERT_TRUE(tools::ParseNumberList("1,-2.5, 3e2 ,+4", &values));
  EXPECT_EQ(values, (std::vector<double>{1, -2.5, 300, 4}));
  ASSERT_TRUE(tools::ParseNumberList("7", &values));
  EXPECT_EQ(values, (std::vector<double>{7}));
  // No text, no numbers (callers check the count they need).
  ASSERT_TRUE(tools::ParseNumberList("", &values));
  EXPECT_TRUE(values.empty());
}

TEST(ParseNumberList, RejectsEmptyItemsAndTrailingCommas) {
  const char* kBad[] = {
      "1,0,0,0,0,1,0,0,0,0,1,0,",  // Trailing comma after 12 numbers.
      "1,2,",
      ",",
      ",1",
      "1,,2",
      "1, ,2",
      " ",
      "1,2,\t",
  };
  for (const char* text : kBad) {
    std::vector<double> values;
    EXPECT_FALSE(tools::ParseNumberList(text, &values)) << "'" << text << "'";
  }
}

TEST(ParseNumberList, RejectsNonNumbersAndNonFinite) {
  for (const char* text : {"1,x", "1,2 3", "nan", "1,inf", "1e999", "--1"}) {
    std::vector<double> values;
    EXPECT_FALSE(tools::ParseNumberList(text, &values)) << "'" << text << "'";
  }
}

std::string AlignPair() {
  const std::string koide3 = testing::BundledDataPath("koide3/");
  return "--reference=" + testing::ShellQuote(koide3 + "251370668.pcd") +
         " --input=" + testing::ShellQuote(koide3 + "251371071.pcd");
}

TEST(MlndtAlign, TrailingCommaInInitialMatrixIsAnError) {
  const testing::ToolRun run = testing::RunTool(
      "mlndt_align",
      AlignPair() + " --initial_matrix=1,0,0,0,0,1,0,0,0,0,1,0,");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--initial_matrix needs 12"), std::string::npos)
      << run.err;
}

TEST(MlndtAlign, FullDiskKeepsThePreviousJsonAndExitsWithOne) {
  testing::SmallFileSystem fs;
  MLNDT_MOUNT_SMALL_FS_OR_SKIP(fs, 64 * 1024);
  const std::string json = fs.path() + "/result.json";
  std::ofstream(json) << "{\"previous\": true}\n";
  fs.Fill();
  const testing::ToolRun run = testing::RunTool(
      "mlndt_align",
      AlignPair() + " --output_json=" + testing::ShellQuote(json));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find(json), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(std::strerror(ENOSPC)), std::string::npos) << run.err;
  EXPECT_EQ(testing::ReadWholeFile(json), "{\"previous\": true}\n");
}

TEST(MlndtAlign, RefusesASymlinkAsOutputJson) {
  const std::string folder = testing::ScratchPath("link");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::string victim = folder + "/victim.txt";
  std::ofstream(victim) << "victim";
  const std::string link = folder + "/result.json";
  ASSERT_EQ(::symlink(victim.c_str(), link.c_str()), 0);
  const testing::ToolRun run = testing::RunTool(
      "mlndt_align",
      AlignPair() + " --output_json=" + testing::ShellQuote(link));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("symbolic link"), std::string::npos) << run.err;
  EXPECT_EQ(testing::ReadWholeFile(victim), "victim");
  EXPECT_TRUE(std::filesystem::is_symlink(link));
}

}  // namespace
}  // namespace mlndt
