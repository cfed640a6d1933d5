// Runs the built mlndt_align binary, the README's main job, on the bundled
// koide3 pair and checks what it writes: the recovered transform against the
// pair's reference result, the timing and memory fields, and clear failures
// on bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;

ToolRun RunAlign(const std::string& args) {
  return testing::RunTool("mlndt_align", args);
}

std::string TestDir() {
  const std::string dir =
      ::testing::TempDir() + "mlndt_align_test_" +
      ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The number after "key": in the tool's JSON (keys are unique there); NaN
// when missing.
double JsonNumber(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\": ";
  const size_t at = json.find(pattern);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + pattern.size(), nullptr);
}

TEST(MlndtAlign, BundledPairMatchesTheReferenceResultAndReportsTimeAndMemory) {
  const std::string json_path = TestDir() + "/result.json";
  const ToolRun run = RunAlign("--output_json=" + Quote(json_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("vs expected:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("map memory:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("peak memory:"), std::string::npos) << run.out;

  const std::string json = testing::ReadWholeFile(json_path);
  ASSERT_FALSE(json.empty());
  EXPECT_NE(json.find("\"converged\": true"), std::string::npos) << json;
  // fast_gicp's tolerance on this pair (PEERS.md 1a); we measured 1.55 cm.
  EXPECT_LT(JsonNumber(json, "translation_error_m"), 0.05);
  EXPECT_LT(JsonNumber(json, "rotation_error_deg"), 1.0);

  const double total = JsonNumber(json, "total");
  const double map = JsonNumber(json, "map");
  const double sampling = JsonNumber(json, "sampling");
  const double solve = JsonNumber(json, "solve");
  EXPECT_GT(map, 0.0);
  EXPECT_GT(sampling, 0.0);
  EXPECT_GT(solve, 0.0);
  EXPECT_GE(total, map + sampling + solve);

  // Every occupied cell holds at least its NdtCell-sized record.
  const double cells = JsonNumber(json, "map_occupied_cells");
  const double bytes = JsonNumber(json, "map_bytes");
  EXPECT_GT(cells, 100.0);
  EXPECT_GE(bytes, cells * 200.0);
  EXPECT_LT(bytes, cells * 2000.0);
  // Two ~70k-point clouds are loaded: at least 2 x 69k x 24 bytes.
  EXPECT_GT(JsonNumber(json, "peak_resident_bytes"),
            2 * 69000 * sizeof(Eigen::Vector3d));
}

TEST(MlndtAlign, BadInputFailsWithAMessage) {
  const std::string dir = TestDir();
  {
    std::ofstream bad(dir + "/bad.pcd");
    bad << "VERSION .7\nFIELDS x y z\nthis is not a pcd\n";
  }
  const std::string reference =
      testing::BundledDataPath("koide3/251370668.pcd");
  struct Case {
    std::string args;
    std::string message;
  } cases[] = {
      {"--reference=" + Quote(reference), "give both --reference and --input"},
      {"--reference=" + Quote(reference) +
           " --input=" + Quote(dir + "/missing.pcd"),
       "missing.pcd"},
      {"--reference=" + Quote(reference) +
           " --input=" + Quote(dir + "/bad.pcd"),
       "bad.pcd"},
      {"--backend=simplex", "simplex"},
      {"--threads=0", "threads"},
      {"stray_argument", "unexpected argument"},
  };
  for (const Case& c : cases) {
    const ToolRun run = RunAlign(c.args);
    EXPECT_NE(run.exit_code, 0) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << "\nstderr: " << run.err;
  }
}

}  // namespace
}  // namespace mlndt
