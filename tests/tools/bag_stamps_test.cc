// The tools whose outputs are stamped (mlndt_sequence, mlndt_localize,
// mlndt_odometry) refuse a bag whose header stamps repeat, are all 0 (a
// driver that does not stamp) or go back: exit 2 before any work, naming
// the message, and no output written (not an abort after the whole run).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_bag.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::RunTool;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

struct BadStamps {
  const char* name;
  const char* stamps;    // One a line, for 3 scans.
  const char* expected;  // In the refusal.
};

const BadStamps kBadStamps[] = {
    {"repeated", "5\n5\n5\n", "stamp 5.000000000 s of message 1 is not after"},
    {"zero", "0\n0\n0\n", "stamp 0.000000000 s of message 1 is not after"},
    {"backwards", "7\n8\n7.5\n", "stamp 7.500000000 s of message 2"},
};

// A bag of the bundled KITTI frames 0-2 with `stamps` as header stamps.
std::string WriteBag(const std::string& dir, const BadStamps& bad) {
  const std::string stamps = dir + "/" + bad.name + ".txt";
  std::ofstream(stamps) << bad.stamps;
  std::vector<std::string> scans;
  for (int i = 0; i < 3; ++i) {
    scans.push_back(testing::BundledDataPath("kitti/pcd/00000" +
                                             std::to_string(i) + ".pcd"));
  }
  const std::string bag = dir + "/" + bad.name + ".bag";
  std::string error;
  EXPECT_TRUE(testing::WriteTestBag(
      bag, "/points", scans, "--header_stamps=" + Quote(stamps), &error))
      << error;
  return bag;
}

TEST(BagStamps, ToolsRefuseStampsThatDoNotIncreaseBeforeAnyWork) {
  MLNDT_REQUIRE_ROSBAG();
  const std::string dir = testing::FreshTestDir("bag_stamps");
  // Any regular file passes --map's check; the bag is refused before the
  // map is read.
  const std::string map = dir + "/map.mlndt";
  std::ofstream(map) << "not read";
  for (const BadStamps& bad : kBadStamps) {
    SCOPED_TRACE(bad.name);
    const std::string bag = WriteBag(dir, bad);
    const std::string out = dir + "/out_" + bad.name;
    const std::string common =
        "--bag=" + Quote(bag) +
        " --topic=/points --plots=false --output_dir=" + Quote(out);
    for (const std::string& tool :
         {"mlndt_sequence", "mlndt_odometry", "mlndt_localize"}) {
      SCOPED_TRACE(tool);
      const std::string extra =
          tool == "mlndt_localize" ? " --map=" + Quote(map) : "";
      const ToolRun run = RunTool(tool, common + extra, 120);
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_NE(run.err.find(bad.expected), std::string::npos) << run.err;
      EXPECT_NE(run.err.find("strictly increasing time stamps"),
                std::string::npos)
          << run.err;
      EXPECT_EQ(run.err.find("Check failed"), std::string::npos) << run.err;
      EXPECT_FALSE(std::filesystem::exists(out)) << "output written";
    }
  }
}

}  // namespace
}  // namespace mlndt
