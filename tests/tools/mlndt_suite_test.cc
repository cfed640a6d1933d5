// Runs the built mlndt_suite: on the bundled KITTI frames (7 consecutive
// pairs, identity and one offset) the printed tables and summary.json
// agree with runs.csv row by row; perturbed starts carry their bound as the
// uncertainty; --fail_on sets the exit code; --plot writes quality.png;
// every misconfiguration is refused before any work, naming the flag; with
// MLNDT_DATA_DIR, the scans of the five shared data sets are found.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/test_data.h"
#include "tests/testing/text_table.h"

namespace mlndt {
namespace {

using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string TestDir() { return testing::FreshTestDir("mlndt_suite"); }

// runs.csv as one map (column -> value) per row.
std::vector<std::map<std::string, std::string>> ReadCsv(
    const std::string& path) {
  std::vector<std::string> lines =
      testing::Split(testing::ReadWholeFile(path), '\n');
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  const std::vector<std::string> header = testing::Split(lines[0], ',');
  for (size_t k = 1; k < lines.size(); ++k) {
    if (lines[k].empty()) continue;
    // No field of these runs holds a comma (messages are plain).
    const std::vector<std::string> fields = testing::Split(lines[k], ',');
    EXPECT_EQ(fields.size(), header.size()) << lines[k];
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < header.size() && c < fields.size(); ++c) {
      row[header[c]] = fields[c];
    }
    rows.push_back(row);
  }
  return rows;
}

// The cells of the first stdout table row whose first cell is `name`.
std::vector<std::string> Row(const ToolRun& run, const std::string& name) {
  for (const std::string& line : run.lines) {
    const std::vector<std::string> cells = testing::TableCells(line);
    if (line[0] == '|' && !cells.empty() && cells[0] == name) return cells;
  }
  return {};
}

double Number(const std::string& text) { return testing::ToNumber(text); }

TEST(MlndtSuite, BundledKittiTablesAgreeWithRunsCsv) {
  const std::string dir = TestDir();
  const ToolRun run = testing::RunTool(
      "mlndt_suite",
      "--datasets=" + Quote(testing::BundledDataPath("kitti")) +
          " --steps=1 --starts=identity,offsets --offsets=x:2 --output_dir=" +
          Quote(dir));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto rows = ReadCsv(dir + "/runs.csv");
  ASSERT_EQ(rows.size(), 14u);
  // Pairs in order, identity then the offset.
  for (size_t k = 0; k < rows.size(); ++k) {
    const auto& r = rows[k];
    EXPECT_EQ(r.at("dataset"), "kitti");
    EXPECT_EQ(r.at("pair"),
              std::to_string(k / 2) + "_" + std::to_string(k / 2 + 1));
    EXPECT_EQ(r.at("step"), "1");
    EXPECT_EQ(r.at("start"), k % 2 == 0 ? "identity" : "x=2");
    EXPECT_EQ(r.at("start_kind"), k % 2 == 0 ? "identity" : "offsets");
    if (k % 2 == 1) EXPECT_NEAR(Number(r.at("start_error_m")), 2.0, 1e-6);
    // right = strictly within 0.2 m and 1°.
    const bool right = Number(r.at("translation_error_m")) < 0.2 &&
                       Number(r.at("rotation_error_deg")) < 1.0;
    EXPECT_EQ(r.at("right"), right ? "1" : "0");
    for (const char* column : {"inlier_fraction",
                               "mean_score",
                               "own_cell_fraction",
                               "median_distance",
                               "constraint_ratio",
                               "attempts",
                               "iterations",
                               "registration_ms"}) {
      EXPECT_TRUE(std::isfinite(Number(r.at(column)))) << column;
    }
  }
  // The confusion table counts runs.csv's rows.
  std::map<std::string, int> right_count, wrong_count;
  int right_total = 0;
  for (const auto& r : rows) {
    const bool right = r.at("right") == "1";
    ++(right ? right_count : wrong_count)[r.at("termination")];
    right_total += right;
  }
  const std::vector<std::string> header = Row(run, "pose");
  const std::vector<std::string> right_row = Row(run, "right");
  const std::vector<std::string> wrong_row = Row(run, "wrong");
  ASSERT_EQ(header.size(), 7u) << run.out;
  ASSERT_EQ(right_row.size(), header.size());
  ASSERT_EQ(wrong_row.size(), header.size());
  const Json summary =
      Json::parse(testing::ReadWholeFile(dir + "/summary.json"));
  EXPECT_EQ(summary["schema_version"], 2);
  EXPECT_EQ(summary["tool"], "mlndt_suite");
  EXPECT_GT(summary["time_ms"]["total"].get<double>(), 0.0);
  for (size_t c = 1; c + 1 < header.size(); ++c) {
    EXPECT_EQ(Number(right_row[c]), right_count[header[c]]) << header[c];
    EXPECT_EQ(Number(wrong_row[c]), wrong_count[header[c]]) << header[c];
    const Json& counts = summary["confusion"]["counts"][header[c]];
    EXPECT_EQ(counts["right"].get<int>(), right_count[header[c]]);
    EXPECT_EQ(counts["wrong"].get<int>(), wrong_count[header[c]]);
  }
  EXPECT_EQ(Number(right_row.back()), right_total);
  EXPECT_EQ(summary["confusion"]["runs"].get<int>(), 14);
  const int convergence =
      right_count["CONVERGENCE"] + wrong_count["CONVERGENCE"];
  if (convergence > 0) {
    EXPECT_NEAR(summary["confusion"]["precision"].get<double>(),
                double(right_count["CONVERGENCE"]) / convergence,
                1e-9);
  }
  // Per start: 7 runs each, right as in runs.csv.
  for (const std::string start : {"identity", "offsets"}) {
    int runs = 0, right = 0;
    for (const auto& r : rows) {
      if (r.at("start_kind") != start) continue;
      ++runs;
      right += r.at("right") == "1";
    }
    bool found = false;
    for (const std::string& line : run.lines) {
      const std::vector<std::string> cells = testing::TableCells(line);
      if (cells.size() == 8 && cells[0] == "kitti" && cells[1] == start) {
        found = true;
        EXPECT_EQ(Number(cells[2]), 7);
        EXPECT_EQ(Number(cells[2]), runs);
        EXPECT_EQ(Number(cells[3]), right);
      }
    }
    EXPECT_TRUE(found) << start << "\n" << run.out;
  }
  // The reach row of the offset.
  int offset_right = 0;
  for (const auto& r : rows) {
    offset_right += r.at("start") == "x=2" && r.at("right") == "1";
  }
  const std::vector<std::string> reach = Row(run, "x=2");
  ASSERT_EQ(reach.size(), 3u) << run.out;
  EXPECT_NE(reach[1].find("(" + std::to_string(offset_right) + "/7)"),
            std::string::npos)
      << reach[1];
  EXPECT_EQ(summary["reach"]["offsets"][0]["all"]["right"].get<int>(),
            offset_right);
  // Accuracy of the identity runs, from runs.csv.
  const std::vector<std::string> accuracy = Row(run, "kitti");
  double sum2 = 0.0;
  int n = 0;
  for (const auto& r : rows) {
    if (r.at("start") != "identity" || r.at("right") != "1") continue;
    sum2 += std::pow(Number(r.at("translation_error_m")), 2);
    ++n;
  }
  bool accuracy_found = false;
  for (const std::string& line : run.lines) {
    const std::vector<std::string> cells = testing::TableCells(line);
    if (cells.size() == 7 && cells[0] == "kitti" && cells[1] == "identity") {
      accuracy_found = true;
      EXPECT_EQ(Number(cells[2]), n);
      EXPECT_NEAR(Number(cells[3]), 100.0 * std::sqrt(sum2 / n), 0.051);
    }
  }
  EXPECT_TRUE(accuracy_found) << run.out;
}

TEST(MlndtSuite, PerturbedStartsCarryTheirBound) {
  const std::string dir = TestDir();
  const ToolRun run = testing::RunTool(
      "mlndt_suite",
      "--datasets=" + Quote(testing::BundledDataPath("koide3")) +
          " --starts=perturbed --perturb=0.5,5 --perturb_count=3 "
          "--output_dir=" +
          Quote(dir));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = ReadCsv(dir + "/runs.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (size_t k = 0; k < rows.size(); ++k) {
    const auto& r = rows[k];
    EXPECT_EQ(r.at("start"), "perturbed#" + std::to_string(k));
    EXPECT_EQ(Number(r.at("uncertainty_m")), 0.5);
    EXPECT_EQ(Number(r.at("uncertainty_deg")), 5.0);
    EXPECT_LE(Number(r.at("start_error_m")), 0.5);
    EXPECT_LE(Number(r.at("start_error_deg")), 5.0);
    EXPECT_GT(Number(r.at("start_error_m")), 0.0);
  }
}

TEST(MlndtSuite, FailOnSetsTheExitCode) {
  // The room scans are 40° apart: from the identity the run is wrong.
  const std::string room =
      "--datasets=" + Quote(testing::BundledDataPath("room")) +
      ":0.1:1 --starts=identity --yaw_seeds_deg=";
  ToolRun run =
      testing::RunTool("mlndt_suite", room + " --fail_on=success:0.5");
  EXPECT_EQ(run.exit_code, 1) << run.err << run.out;
  EXPECT_NE(run.out.find("target missed: success 0 < 0.5"), std::string::npos)
      << run.out;
  run = testing::RunTool(
      "mlndt_suite",
      "--datasets=" + Quote(testing::BundledDataPath("koide3")) +
          " --starts=identity --fail_on=success:1");
  EXPECT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_EQ(run.out.find("target missed"), std::string::npos) << run.out;
}

TEST(MlndtSuite, PlotWritesTheQualityCurves) {
  if (std::system("gnuplot --version >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "gnuplot is not installed";
  }
  const std::string dir = TestDir();
  const ToolRun run = testing::RunTool(
      "mlndt_suite",
      "--datasets=" + Quote(testing::BundledDataPath("koide3")) +
          " --starts=identity,offsets --offsets=yaw:10,150 "
          "--yaw_seeds_deg= --plot --output_dir=" +
          Quote(dir));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GT(fs::file_size(dir + "/quality.png"), 1000u);
  EXPECT_TRUE(fs::exists(dir + "/plot_data/inlier_fraction_right.txt"));
  EXPECT_TRUE(fs::exists(dir + "/plot_data/median_distance_wrong.txt"));
}

// A data set folder of copies of the bundled koide3 scans under other names.
std::string MakeDataset(const std::string& dir,
                        const std::vector<std::string>& scans,
                        const std::string& pairs_json) {
  fs::create_directories(dir);
  for (const std::string& name : scans) {
    fs::copy_file(testing::BundledDataPath("koide3/251370668.pcd"),
                  dir + "/" + name,
                  fs::copy_options::overwrite_existing);
  }
  std::ofstream(dir + "/reference_pairs.json") << pairs_json;
  return dir;
}

std::string PairJson(const std::string& key) {
  return "{\"" + key +
         "\": {\"reference_from_input\": [1,0,0,0, 0,1,0,0, 0,0,1,0], "
         "\"spread_m\": 0, \"spread_deg\": 0}}";
}

TEST(MlndtSuite, RefusesBadInputBeforeAnyWork) {
  const std::string dir = TestDir();
  const std::string kitti =
      "--datasets=" + Quote(testing::BundledDataPath("kitti")) + " ";
  const std::string missing =
      MakeDataset(dir + "/missing", {"scan0.pcd"}, PairJson("0_9"));
  const std::string ambiguous = MakeDataset(
      dir + "/ambiguous", {"scan1.pcd", "0001.pcd", "2.pcd"}, PairJson("1_2"));
  const std::string out = " --output_dir=" + Quote(dir + "/out");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "--datasets is required"},
      {kitti + "--starts=identity,bogus", "--starts: 'bogus'"},
      {kitti + "--starts=identity,identity", "twice"},
      {kitti + "--starts=identity --offsets=x:1", "--offsets needs offsets"},
      {kitti + "--starts=offsets --offsets=q:1", "--offsets: 'q:1'"},
      {kitti + "--starts=identity --perturb=1,1", "--perturb needs perturbed"},
      {kitti + "--starts=identity --perturb_count=2", "--perturb_count needs"},
      {kitti + "--starts=perturbed --perturb=1", "--perturb=1"},
      {kitti + "--starts=perturbed --perturb_count=0", "--perturb_count"},
      {kitti + "--starts=perturbed --initial_uncertainty=1,1",
       "--initial_uncertainty"},
      {kitti + "--starts=identity --prior_uncertainty=1,1",
       "--prior_uncertainty needs prior"},
      {kitti + "--starts=prior --prior_uncertainty=1", "--prior_uncertainty"},
      {kitti + "--starts=prior --prior_uncertainty=1,1 --method=ndt",
       "--prior_uncertainty does not apply"},
      {kitti + "--steps=1,a", "--steps"},
      {kitti + "--steps=0", "--steps"},
      {kitti + "--max_pairs_per_set=-1", "--max_pairs_per_set"},
      {kitti + "--reach_share=0", "--reach_share"},
      {kitti + "--fail_on=precision:2", "--fail_on"},
      {kitti + "--fail_on=accuracy:0.5", "--fail_on"},
      {kitti + "--plot", "--plot needs --output_dir"},
      {kitti + "--plot --gnuplot=/nonexistent/gnuplot" + out,
       "--plot: gnuplot"},
      {kitti + "--gnuplot=gnuplot", "--gnuplot needs --plot"},
      {kitti + "--backend=bogus", "--backend"},
      {kitti + "extra", "unexpected argument"},
      {"--datasets=" + Quote(testing::BundledDataPath("kitti")) + ":0.2",
       "--datasets item"},
      {"--datasets=" + Quote(testing::BundledDataPath("kitti")) + ":0:1",
       "--datasets item"},
      {"--datasets=" + Quote(testing::BundledDataPath("kitti")) + "," +
           Quote(testing::BundledDataPath("kitti")),
       "two data sets named 'kitti'"},
      {"--datasets=" + Quote(dir + "/nonexistent"), "not a folder"},
      {"--data_dir=" + Quote(dir + "/nonexistent") + " --datasets=kitti",
       "--data_dir"},
      {"--datasets=" + Quote(testing::BundledDataPath("")) + out,
       "reference_pairs.json"},
      {"--datasets=" + Quote(missing) + out, "no scan file numbered 9"},
      {"--datasets=" + Quote(ambiguous) + out, "scan 1 is ambiguous"},
  };
  for (const auto& [args, expected] : cases) {
    const ToolRun run = testing::RunTool("mlndt_suite", args);
    EXPECT_EQ(run.exit_code, 2) << args;
    EXPECT_NE(run.err.find(expected), std::string::npos)
        << args << "\nstderr: " << run.err;
    EXPECT_TRUE(run.out.empty()) << args << "\n" << run.out;
    EXPECT_FALSE(fs::exists(dir + "/out")) << args;
  }
}

TEST(MlndtSuite, FindsTheScansOfTheSharedDataSets) {
  MLNDT_REQUIRE_SHARED_DATA(shared);
  const ToolRun run = testing::RunTool(
      "mlndt_suite",
      "--data_dir=" + Quote(shared) +
          " --datasets=kitti00_frames_0000_0007,mulran_kaist03_keyframes,"
          "3dtk_example_scans:0.1:1,pcl_room_scans:0.1:1,koide3_velodyne_pair"
          " --starts=prior --max_pairs_per_set=1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"kitti00_frames_0000_0007",
                           "mulran_kaist03_keyframes",
                           "3dtk_example_scans",
                           "pcl_room_scans",
                           "koide3_velodyne_pair"}) {
    bool found = false;
    for (const std::string& line : run.lines) {
      const std::vector<std::string> cells = testing::TableCells(line);
      if (cells.size() == 8 && cells[0] == name && cells[1] == "prior") {
        found = true;
        EXPECT_EQ(cells[2], "1") << line;  // One run.
      }
    }
    EXPECT_TRUE(found) << name << "\n" << run.out;
  }
}

}  // namespace
}  // namespace mlndt
