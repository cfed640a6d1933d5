// Runs the built mlndt_bench binary (tests/testing/test_data.h ToolPath) on
// the bundled koide3 pair and checks its markdown table, CSV and exit codes.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"
#include "tests/testing/text_table.h"

namespace mlndt {
namespace {

using testing::Split;
using testing::TableCells;
using testing::ToNumber;
using testing::ToolRun;
const auto& Quote = testing::ShellQuote;
const auto& ReadFile = testing::ReadWholeFile;

std::string TempPath(const std::string& name) {
  return testing::ScratchPath(name);
}

// Runs mlndt_bench with `args` (already quoted where needed); stderr goes to
// a file named after the current test, since ctest may run tests in parallel.
// The warm sets only (the one-shot ones repeat every pair in a child
// process; tests/lab/bench/bench_rounds_test.cc tests them).
ToolRun RunBench(const std::string& args) {
  return testing::RunTool("mlndt_bench", args + " --one_shot=false");
}

const char kCsvHeader[] =
    "pairs,defaults,method,backend,sampling,start_layer,linear_solver,trust_"
    "region,minimizer,jacobians,loss,"
    "threads,runs,"
    "time_median_ms,time_min_ms,time_max_ms,mean_iterations,mean_point_"
    "iterations,mean_final_score,"
    "mean_translation_error_m,max_translation_error_m,mean_rotation_error_deg,"
    "max_rotation_error_deg,converged_rate,success_rate,nees_mean,nees_median,"
    "pcl_time_median_ms,pcl_over_ours";

TEST(MlndtBench, NewtonAndLmOnTheKoide3Pair) {
  const std::string csv_path = TempPath("koide3.csv");
  std::remove(csv_path.c_str());
  const ToolRun run = RunBench(
      "--repetitions=1 --pairs=koide3 --backends=newton,lm --output_csv=" +
      Quote(csv_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // Markdown table: a header, a rule and one row per backend.
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : run.lines) {
    if (line.rfind("|", 0) == 0 && line.find("---") == std::string::npos) {
      rows.push_back(TableCells(line));
    }
  }
  ASSERT_EQ(rows.size(), 3u) << "header + 2 rows expected";
  const std::vector<std::string>& header = rows[0];
  ASSERT_GE(header.size(), 2u);
  EXPECT_EQ(header[0], "pairs");
  EXPECT_EQ(header[1], "defaults");
  EXPECT_EQ(header[2], "method");
  EXPECT_EQ(rows[1][2], "newton");
  EXPECT_EQ(rows[2][2], "lm");
  for (size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r].size(), header.size());
    EXPECT_EQ(rows[r][0], "koide3");
  }

  // CSV: the header and one row per backend.
  const std::vector<std::string> lines = Split(ReadFile(csv_path), '\n');
  ASSERT_EQ(lines.size(), 4u) << "header, 2 rows and a final newline expected";
  EXPECT_EQ(lines[3], "");
  ASSERT_EQ(lines[0], kCsvHeader);
  const std::vector<std::string> names = Split(lines[0], ',');
  const std::vector<std::string> backends = {"newton", "lm"};
  for (size_t r = 0; r < backends.size(); ++r) {
    SCOPED_TRACE(lines[r + 1]);
    const std::vector<std::string> values = Split(lines[r + 1], ',');
    ASSERT_EQ(values.size(), names.size());
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < names.size(); ++c) row[names[c]] = values[c];
    EXPECT_EQ(row["pairs"], "koide3");
    EXPECT_EQ(row["method"], "mlndt");
    EXPECT_EQ(row["backend"], backends[r]);
    EXPECT_EQ(row["runs"], "1");
    EXPECT_EQ(row["linear_solver"], "");  // Ceres only.
    EXPECT_EQ(row["pcl_over_ours"], "");  // No --compare_pcl.
    EXPECT_EQ(row["defaults"], "current");
    // Against the consensus in koide3/reference_pairs.json (spread 3.3 cm,
    // 0.48 deg).
    const double translation_error = ToNumber(row["mean_translation_error_m"]);
    const double rotation_error = ToNumber(row["mean_rotation_error_deg"]);
    ASSERT_TRUE(std::isfinite(translation_error));
    ASSERT_TRUE(std::isfinite(rotation_error));
    EXPECT_LT(translation_error, 0.03);
    EXPECT_LT(rotation_error, 0.5);
    EXPECT_EQ(ToNumber(row["success_rate"]), 1.0);
    const double time = ToNumber(row["time_median_ms"]);
    EXPECT_GT(time, 0.0);
    EXPECT_EQ(ToNumber(row["time_min_ms"]), time);  // One round.
    EXPECT_EQ(ToNumber(row["time_max_ms"]), time);
    EXPECT_GT(ToNumber(row["mean_iterations"]), 0.0);
    // The koide3 input keeps ~4k samples; every iteration evaluates at
    // least every 8th of them (the coarse layers' stride).
    EXPECT_GE(ToNumber(row["mean_point_iterations"]),
              ToNumber(row["mean_iterations"]) * 4000 / 8);
    EXPECT_TRUE(std::isfinite(ToNumber(row["mean_final_score"])));
  }
}

// The previous defaults (2 m finest cells, Cauchy scale 3) build another
// map: another final score, both near the reference.
TEST(MlndtBench, CurrentAndPreviousDefaultsOnTheKoide3Pair) {
  const std::string csv_path = TempPath("defaults.csv");
  const ToolRun run = RunBench(
      "--repetitions=1 --pairs=koide3 --backends=lm "
      "--defaults=current,previous --output_csv=" +
      Quote(csv_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> lines = Split(ReadFile(csv_path), '\n');
  ASSERT_EQ(lines.size(), 4u);
  const std::vector<std::string> names = Split(lines[0], ',');
  std::map<std::string, std::map<std::string, std::string>> rows;
  for (int r = 1; r <= 2; ++r) {
    const std::vector<std::string> values = Split(lines[r], ',');
    ASSERT_EQ(values.size(), names.size());
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < names.size(); ++c) row[names[c]] = values[c];
    rows[row["defaults"]] = row;
  }
  ASSERT_EQ(rows.count("current"), 1u);
  ASSERT_EQ(rows.count("previous"), 1u);
  // Each with its own Cauchy scale (issue 41 item 5).
  EXPECT_EQ(rows["current"]["loss"], "cauchy@1.5");
  EXPECT_EQ(rows["previous"]["loss"], "cauchy@3");
  EXPECT_NE(rows["current"]["mean_final_score"],
            rows["previous"]["mean_final_score"]);
  for (auto& [name, row] : rows) {
    EXPECT_LT(ToNumber(row["mean_translation_error_m"]), 0.03) << name;
  }
}

// The CSV's rows by column name.
std::vector<std::map<std::string, std::string>> CsvRows(
    const std::string& path) {
  const std::vector<std::string> lines = Split(ReadFile(path), '\n');
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  const std::vector<std::string> names = Split(lines[0], ',');
  for (size_t r = 1; r < lines.size(); ++r) {
    if (lines[r].empty()) continue;
    const std::vector<std::string> values = Split(lines[r], ',');
    EXPECT_EQ(values.size(), names.size()) << lines[r];
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < names.size() && c < values.size(); ++c)
      row[names[c]] = values[c];
    rows.push_back(row);
  }
  return rows;
}

// Any folder with a reference_pairs.json (here data/kitti) from its priors
// and an offset, with the Jacobian and loss axes, the CSV and the plot.
TEST(MlndtBench, AnyFolderFromPriorsAndOffsetsWithNewAxes) {
  const std::string csv_path = TempPath("folder.csv");
  const std::string png_path = TempPath("folder.png");
  for (const std::string& f : {csv_path, png_path, png_path + ".dat"})
    std::remove(f.c_str());
  const ToolRun run = RunBench(
      "--data_dir=" + Quote(testing::BundledDataPath("kitti")) +
      " --starts=prior,offsets --offsets=x:1 --max_pairs=2 --repetitions=1 "
      "--warmup=false --backends=ceres --jacobians=autodiff,analytic "
      "--losses=none,cauchy --output_csv=" +
      Quote(csv_path) + " --output_plot=" + Quote(png_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = CsvRows(csv_path);
  // 2 sets (kitti/prior, kitti/offsets) x 2 Jacobians x 2 losses.
  ASSERT_EQ(rows.size(), 8u);
  std::map<std::string, double> error;  // By set, loss and Jacobians.
  for (const auto& row : rows) {
    const std::string set = row.at("pairs");
    EXPECT_TRUE(set == "kitti/prior" || set == "kitti/offsets") << set;
    EXPECT_EQ(row.at("runs"), "2") << set;
    EXPECT_EQ(row.at("minimizer"), "trust_region");
    // Consistent covariances give 6; these are optimistic, never below 1.
    EXPECT_GT(ToNumber(row.at("nees_mean")), 1.0) << set;
    error[set + row.at("loss") + row.at("jacobians")] =
        ToNumber(row.at("mean_translation_error_m"));
    if (row.at("loss") == "cauchy@1.5") {
      EXPECT_EQ(ToNumber(row.at("success_rate")), 1.0) << set;
      EXPECT_LT(ToNumber(row.at("mean_translation_error_m")), 0.05) << set;
    }
  }
  for (const std::string set : {"kitti/prior", "kitti/offsets"}) {
    for (const std::string loss : {"none", "cauchy@1.5"}) {
      // The same residual differentiated two ways: the same answers.
      EXPECT_NEAR(
          error[set + loss + "analytic"], error[set + loss + "autodiff"], 1e-4)
          << set << " " << loss;
    }
    // Without a loss the nearest-cell residuals of the far points pull the
    // pose off (22 cm here): the loss axis measures something.
    EXPECT_GT(error[set + "noneautodiff"],
              2.0 * error[set + "cauchy@1.5autodiff"])
        << set;
  }
  // The plot: a PNG and its data, one Pareto point at least per set.
  std::ifstream png(png_path, std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  const std::string data = ReadFile(png_path + ".dat");
  EXPECT_NE(data.find("# kitti/prior"), std::string::npos) << data;
  EXPECT_NE(data.find("# kitti/offsets"), std::string::npos) << data;
  EXPECT_NE(data.find(" 1 \""), std::string::npos) << data;
}

// The bundled PCL room pair (40 deg apart) from its prior: a folder whose
// scans are named, not numbered, and whose pairs need a start.
TEST(MlndtBench, RoomFolderFromItsPrior) {
  const std::string csv_path = TempPath("room.csv");
  std::remove(csv_path.c_str());
  const ToolRun run =
      RunBench("--data_dir=" + Quote(testing::BundledDataPath("room")) +
               " --starts=prior --backends=lm --repetitions=1 --warmup=false "
               "--output_csv=" +
               Quote(csv_path));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = CsvRows(csv_path);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("pairs"), "room/prior");
  EXPECT_EQ(rows[0].at("runs"), "1");
  EXPECT_EQ(ToNumber(rows[0].at("success_rate")), 1.0);
  EXPECT_LT(ToNumber(rows[0].at("mean_translation_error_m")), 0.05);
}

// PCL's GICP as another row (in the build with PCL); without PCL the flag is
// refused before any work.
TEST(MlndtBench, ComparePclGicp) {
  const std::string csv_path = TempPath("gicp.csv");
  std::remove(csv_path.c_str());
  const ToolRun run = RunBench(
      "--pairs=koide3 --backends=lm --repetitions=1 --warmup=false "
      "--compare_pcl_gicp --output_csv=" +
      Quote(csv_path));
#ifdef MLNDT_WITH_PCL
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto rows = CsvRows(csv_path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("method"), "mlndt");
  EXPECT_EQ(rows[1].at("method"), "pcl_gicp");
  EXPECT_EQ(rows[1].at("sampling"), "voxel_grid_0.25");  // The harness's.
  EXPECT_EQ(ToNumber(rows[1].at("success_rate")), 1.0);
  EXPECT_LT(ToNumber(rows[1].at("mean_translation_error_m")), 0.05);
  // GICP is the ratio's numerator when it runs; ours is faster here.
  EXPECT_GT(ToNumber(rows[0].at("pcl_over_ours")), 1.0);
  EXPECT_EQ(rows[1].at("pcl_over_ours"), "");  // Not for the peer's row.
  EXPECT_NE(run.out.find("+ pcl::GICP"), std::string::npos) << run.out;
#else
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find("--compare_pcl_gicp: this build has no PCL"),
            std::string::npos)
      << run.err;
#endif
}

TEST(MlndtBench, UnknownBackendFails) {
  const ToolRun run =
      RunBench("--repetitions=1 --pairs=koide3 --backends=newton,foo");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.lines.empty());
  EXPECT_NE(run.err.find("--backends"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("foo"), std::string::npos) << run.err;
}

TEST(MlndtBench, RejectsBadFlagValues) {
  for (const std::string flags :
       {"--backends=foo",
        "--pairs=bar",
        "--samplings=none",
        "--threads=1,x",
        "--threads=0",
        "--start_layers=",
        "--gbs_cell_sizes=",
        "--gbs_cell_sizes=x",
        "--gbs_cell_sizes=0",
        "--linear_solvers=cholesky",
        "--trust_regions=newton",
        "--kitti_gaps=0",
        "--starts=constant_velocity",
        "--starts=offsets --offsets=q:1",
        "--max_pairs=-1",
        "--minimizers=newton",
        "--jacobians=numeric",
        "--losses=tukey",
        "--loss_scales=x",
        "--data_dir=/nonexistent",
        "--pairs=koide3 --output_plot=/nonexistent/x.png",
        "--repetitions=0",
        "--pairs=koide3 --output_csv=/nonexistent/x.csv",
        "--pcl_leaf_size_m=0",
        "--pcl_gicp_max_iterations=0",
        "unexpected_argument"}) {
    SCOPED_TRACE(flags);
    const ToolRun run = RunBench(flags);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(run.lines.empty());
    EXPECT_NE(run.err.find("mlndt_bench: "), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace mlndt
