// Runs the built mlndt_scaling binary (tests/testing/test_data.h ToolPath)
// on the bundled KITTI frames with small sizes and checks its table, CSV,
// slopes, the accuracy of the solve and the exit codes on bad flags.
//
// The tool moves the input by 0.5 m, 0.3 m and 2 deg of yaw (its default
// --motion); a solve that does not run or stops early leaves up to 58 cm
// and 2 deg, so the 10 cm / 0.5 deg bounds below catch it. Measured with
// the default 1.2 m finest cells: 2.5 cm / 0.05 deg at 4000 points, 2.0 cm /
// 0.06 deg at 12000 (3000 points are too few for 1.2 m cells: 13 cm).

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
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

namespace fs = std::filesystem;

constexpr double kMaxTranslationErrorCm = 10.0;
constexpr double kMaxRotationErrorDeg = 0.5;

ToolRun RunScaling(const std::string& args) {
  return testing::RunTool("mlndt_scaling", args);
}

bool GnuplotInstalled() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

// Table rows: lines starting with "| <digit>".
std::vector<std::vector<std::string>> TableRows(const ToolRun& run) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : run.lines) {
    if (line.size() > 2 && line.rfind("| ", 0) == 0 &&
        std::isdigit(static_cast<unsigned char>(line[2]))) {
      rows.push_back(TableCells(line));
    }
  }
  return rows;
}

std::string TestDir() { return testing::FreshTestDir("mlndt_scaling"); }

TEST(MlndtScaling, SmallSizesOnTheBundledKittiFrames) {
  const std::string dir = TestDir();
  const bool gnuplot = GnuplotInstalled();
  const ToolRun run = RunScaling(
      "--sizes=4000,12000 --repetitions=1 --output_dir=" + Quote(dir));
  // Without gnuplot the CSV is written and the tool exits 1 for the PNG.
  ASSERT_EQ(run.exit_code, gnuplot ? 0 : 1) << run.out << run.err;
  EXPECT_NE(run.out.find("merged cloud: 991949 points from 8 scans"),
            std::string::npos)
      << run.out;

  // Table: points, map, sampling, solve, total, sampled, cells, layers,
  // iterations, t error cm, r error deg, solve.
  const std::vector<std::vector<std::string>> rows = TableRows(run);
  ASSERT_EQ(rows.size(), 2u) << run.out;
  EXPECT_EQ(rows[0][0], "4000");
  EXPECT_EQ(rows[1][0], "12000");
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 12u) << run.out;
    EXPECT_GT(ToNumber(row[3]), 0.0) << "solve ms, N = " << row[0];
    EXPECT_GT(ToNumber(row[4]), 0.0) << "total ms, N = " << row[0];
    EXPECT_GE(ToNumber(row[1]), 0.0)
        << "map ms, N = " << row[0];  // 0.1 ms resolution.
    EXPECT_GE(ToNumber(row[2]), 0.0) << "sampling ms, N = " << row[0];
    EXPECT_GT(ToNumber(row[5]), 0.0) << "sampled points, N = " << row[0];
    EXPECT_LE(ToNumber(row[5]), ToNumber(row[0]));
    EXPECT_GT(ToNumber(row[6]), 0.0) << "finest-layer cells, N = " << row[0];
    EXPECT_GT(ToNumber(row[8]), 0.0) << "iterations, N = " << row[0];
    EXPECT_LT(ToNumber(row[9]), kMaxTranslationErrorCm) << "N = " << row[0];
    EXPECT_LT(ToNumber(row[10]), kMaxRotationErrorDeg) << "N = " << row[0];
    EXPECT_EQ(row[11], "ok");
  }
  // A slope per stage and total. Only finite: from one wall-clock run of two
  // small sizes its sign is at the mercy of machine noise.
  for (const char* stage : {"map:", "sampling:", "solve:", "total:"}) {
    const size_t at = run.out.find(std::string("  ") + stage);
    ASSERT_NE(at, std::string::npos) << stage << "\n" << run.out;
    const double slope = std::strtod(
        run.out.c_str() + at + 2 + std::string(stage).size(), nullptr);
    EXPECT_TRUE(std::isfinite(slope)) << stage;
  }

  // CSV: the same rows, with full precision.
  const std::vector<std::string> lines =
      Split(ReadFile(dir + "/scaling.csv"), '\n');
  ASSERT_EQ(lines.size(), 4u) << "header, 2 rows and a final newline expected\n"
                              << ReadFile(dir + "/scaling.csv");
  EXPECT_EQ(lines[3], "");
  EXPECT_EQ(lines[0],
            "points,map_ms,sampling_ms,solve_ms,total_ms,sampled_points,finest_"
            "layer_cells,"
            "num_layers,iterations,termination,translation_error_m,rotation_"
            "error_deg,ok");
  for (size_t k = 1; k < 3; ++k) {
    const std::vector<std::string> f = Split(lines[k], ',');
    ASSERT_EQ(f.size(), 13u) << lines[k];
    EXPECT_EQ(f[0], rows[k - 1][0]);
    const double map = ToNumber(f[1]), sampling = ToNumber(f[2]),
                 solve = ToNumber(f[3]), total = ToNumber(f[4]);
    EXPECT_GT(map, 0.0) << lines[k];
    EXPECT_GT(sampling, 0.0) << lines[k];
    EXPECT_GT(solve, 0.0) << lines[k];
    // The total covers the stages (plus bookkeeping).
    EXPECT_GE(total, map + sampling + solve) << lines[k];
    EXPECT_EQ(f[5], rows[k - 1][5]);
    EXPECT_EQ(f[6], rows[k - 1][6]);
    EXPECT_EQ(f[9], "CONVERGENCE") << lines[k];
    EXPECT_LT(ToNumber(f[10]) * 100.0, kMaxTranslationErrorCm) << lines[k];
    EXPECT_LT(ToNumber(f[11]), kMaxRotationErrorDeg) << lines[k];
    EXPECT_EQ(f[12], "1");
  }
  if (gnuplot) {
    EXPECT_TRUE(fs::exists(dir + "/scaling.gp"));
    ASSERT_TRUE(fs::exists(dir + "/scaling.png"));
    EXPECT_GT(fs::file_size(dir + "/scaling.png"), 1000u);
  }
}

TEST(MlndtScaling, WithoutOutputDirPrintsOnlyTheTable) {
  const ToolRun run = RunScaling("--sizes=4000 --repetitions=2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(TableRows(run).size(), 1u) << run.out;
  EXPECT_EQ(run.out.find("output:"), std::string::npos) << run.out;
  // One size gives no slope.
  EXPECT_NE(run.out.find("  map:                –"), std::string::npos)
      << run.out;
}

TEST(MlndtScaling, ErrorAboveTheToleranceIsReportedAndFails) {
  const ToolRun run =
      RunScaling("--sizes=3000 --repetitions=1 --max_translation_error=0.0001");
  EXPECT_EQ(run.exit_code, 1);
  const std::vector<std::vector<std::string>> rows = TableRows(run);
  ASSERT_EQ(rows.size(), 1u) << run.out;
  EXPECT_EQ(rows[0].back(), "LARGE ERROR");
  EXPECT_NE(run.err.find("N = 3000: recovered motion off by"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("did not recover --motion"), std::string::npos)
      << run.err;
}

struct BadFlagCase {
  const char* args;
  const char* message;  // Must appear in stderr.
};

TEST(MlndtScaling, BadFlagsExitNonZeroNamingTheProblem) {
  const BadFlagCase cases[] = {
      {"--sizes=12000,3000",
       "--sizes=12000,3000: sizes must be strictly increasing"},
      {"--sizes=3000,3000", "strictly increasing (3000 after 3000)"},
      {"--sizes=3000,abc",
       "--sizes=3000,abc: expected comma-separated positive integers"},
      {"--sizes=0,3000", "'0' is not a positive integer"},
      {"--sizes=1500.5", "'1500.5' is not a positive integer"},
      {"--sizes=3000,2000000", "2000000 points requested, but the 8 scans"},
      {"--sizes=3000,2000000", "merge into only 991949 points"},
      {"--repetitions=0", "--repetitions=0: must be >= 1"},
      {"--motion=1,2,3", "--motion=1,2,3: expected 6 comma-separated numbers"},
      {"--backend=gauss", "--backend=gauss"},
      {"--scans=/nonexistent_folder", "/nonexistent_folder: not a folder"},
      {"--sizes=1000 stray", "unexpected argument 'stray'"},
  };
  for (const BadFlagCase& c : cases) {
    const ToolRun run = RunScaling(c.args);
    EXPECT_NE(run.exit_code, 0) << c.args;
    EXPECT_NE(run.err.find(c.message), std::string::npos)
        << c.args << ": stderr was\n"
        << run.err;
    EXPECT_TRUE(TableRows(run).empty()) << c.args;
  }
}

}  // namespace
}  // namespace mlndt
