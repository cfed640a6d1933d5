// Runs the built mlndt_covariance binary on the bundled koide3 pair with a
// few starts: its progress bar, its JSON (docs/json_schema.md), its CSV, and
// the flags it refuses before any registration.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

std::string TestDir() { return testing::FreshTestDir("mlndt_covariance"); }

TEST(MlndtCovariance, Koide3StartsShowProgressAndWriteJsonAndCsv) {
  const std::string dir = TestDir();
  const ToolRun run =
      testing::RunTool("mlndt_covariance",
                       "--datasets=koide3 --starts=3 --output_json=" +
                           Quote(dir + "/covariance.json") +
                           " --output_csv=" + Quote(dir + "/runs.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("mlndt_covariance 3/3 koide3"), std::string::npos)
      << run.err;
  const nlohmann::json json = nlohmann::json::parse(
      testing::ReadWholeFile(dir + "/covariance.json"), nullptr, false);
  ASSERT_TRUE(json.is_object());
  EXPECT_EQ(json["schema_version"], 2);
  EXPECT_EQ(json["tool"], "mlndt_covariance");
  EXPECT_EQ(json["koide3"]["consistency"]["runs"], 3);
  EXPECT_EQ(json["koide3"]["failures"], 0);
  // A header and one row per registration.
  const std::string csv = testing::ReadWholeFile(dir + "/runs.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4) << csv;
}

TEST(MlndtCovariance, RefusesFlagsBeforeAnyRegistration) {
  const std::string dir = TestDir();
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"--starts=1", "--starts must be >= 2"},
      {"--datasets=koide3,bogus", "--datasets: unknown 'bogus'"},
      {"--output_csv=" + Quote(dir + "/missing/runs.csv"), "--output_csv"},
      {"--output_json=" + Quote(dir + "/missing/c.json"), "--output_json"},
      {"--method=ndt", "this tool runs ML-NDT only"},
  };
  for (const Case& c : cases) {
    const ToolRun run = testing::RunTool("mlndt_covariance", c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args << "\nstderr: " << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
    EXPECT_EQ(run.err.find("mlndt_covariance 1/"), std::string::npos)
        << c.args << ": a registration ran";
  }
}

}  // namespace
}  // namespace mlndt
