// Runs the built mlndt_convert binary: IN OUT as positional files (or
// --input/--output), and the command lines it refuses with exit 2.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

std::string TestDir() { return testing::FreshTestDir("mlndt_convert"); }

TEST(MlndtConvert, PositionalFilesAndFlagsGiveTheSameCloud) {
  const std::string dir = TestDir();
  const std::string in = testing::BundledDataPath("koide3/251370668.pcd");
  const ToolRun positional = testing::RunTool(
      "mlndt_convert", Quote(in) + " " + Quote(dir + "/a.ply"));
  ASSERT_EQ(positional.exit_code, 0) << positional.err;
  const ToolRun flags = testing::RunTool(
      "mlndt_convert",
      "--input=" + Quote(in) + " --output=" + Quote(dir + "/b.ply"));
  ASSERT_EQ(flags.exit_code, 0) << flags.err;
  EXPECT_EQ(testing::ReadWholeFile(dir + "/a.ply"),
            testing::ReadWholeFile(dir + "/b.ply"));
  EXPECT_NE(positional.out.find("69088 points"), std::string::npos)
      << positional.out;
}

TEST(MlndtConvert, RefusesIncompleteOrAmbiguousCommandLines) {
  const std::string dir = TestDir();
  const std::string in =
      Quote(testing::BundledDataPath("koide3/251370668.pcd"));
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"", "give IN OUT"},
      {in, "expected IN OUT"},
      {in + " a.ply b.ply", "expected IN OUT"},
      {in + " " + Quote(dir + "/x.ply") + " --output=" + Quote(dir + "/y.ply"),
       "not both"},
      {in + " " + Quote(dir + "/missing/x.ply"),
       "--output=" + dir + "/missing/x.ply"},
      {in + " " + Quote(dir + "/x.ply") + " --voxel_size=-1",
       "--voxel_size must be >= 0"},
      {Quote(dir + "/missing.pcd") + " " + Quote(dir + "/x.ply"),
       "missing.pcd"},
  };
  for (const Case& c : cases) {
    const ToolRun run = testing::RunTool("mlndt_convert", c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args << "\nstderr: " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.ply"));
}

}  // namespace
}  // namespace mlndt
