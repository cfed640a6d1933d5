// mlndt_scaling's reports (lab/experiments/scaling_report.h) on the real
// run of docs/scaling_run.txt (KITTI frames 0-7 merged, MLNDT, 5 sizes):
// its table rows reproduced from its values, its log-log slopes recomputed
// from the rounded table (exact for the point counts, within 0.02 for the
// times, whose table values are rounded to 0.1 ms), against a power law
// computed here; scaling.csv, the figure, the broken-solve lines.

#include "lab/experiments/scaling_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/scratch_dir.h"

namespace mlndt {
namespace {

const std::vector<size_t> kSizes = {10000, 30000, 100000, 300000, 990000};

SizeResult Row(size_t points,
               const std::vector<double>& ms,
               size_t sampled,
               size_t cells,
               int iterations,
               double t_cm,
               double r_deg) {
  SizeResult r;
  r.points = points;
  r.map_ms = ms[0];
  r.sampling_ms = ms[1];
  r.solve_ms = ms[2];
  r.total_ms = ms[3];
  r.sampled_points = sampled;
  r.finest_cells = cells;
  r.num_layers = 5;
  r.iterations = iterations;
  r.termination = TerminationType::CONVERGENCE;
  r.translation_error_m = t_cm / 100.0;
  r.rotation_error_deg = r_deg;
  r.ok = true;
  return r;
}

// docs/scaling_run.txt's table.
std::vector<SizeResult> DocsRun() {
  return {
      Row(10000, {0.6, 0.3, 18.7, 20.5}, 3626, 479, 45, 2.39, 0.073),
      Row(30000, {1.2, 0.8, 31.0, 34.6}, 7297, 899, 37, 0.53, 0.021),
      Row(100000, {2.3, 2.2, 68.6, 76.3}, 13837, 1141, 41, 0.51, 0.013),
      Row(300000, {5.9, 5.4, 94.1, 110.4}, 21308, 1675, 37, 0.95, 0.007),
      Row(990000, {19.9, 17.8, 131.6, 178.3}, 30097, 2005, 36, 0.31, 0.002)};
}

TEST(LogLogSlope, RecoversAPowerLawAndRefusesWhatHasNoLog) {
  std::vector<double> x, y;
  for (const size_t n : kSizes) {
    x.push_back(static_cast<double>(n));
    y.push_back(3.0 * std::pow(static_cast<double>(n), 1.5));
  }
  EXPECT_NEAR(LogLogSlope(x, y), 1.5, 1e-12);
  EXPECT_TRUE(std::isnan(LogLogSlope({1.0}, {2.0})));
  EXPECT_TRUE(std::isnan(LogLogSlope({1.0, 2.0}, {1.0, 0.0})));
  EXPECT_TRUE(std::isnan(LogLogSlope({1.0, 2.0}, {1.0})));
}

TEST(ScalingSlopes, ReproduceTheDocumentedRun) {
  const std::vector<double> slopes = ScalingSlopes(kSizes, DocsRun());
  const std::vector<double> documented = {0.74, 0.86, 0.44, 0.48, 0.46, 0.30};
  ASSERT_EQ(slopes.size(), documented.size());
  for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(slopes[k], documented[k], 0.02);
  EXPECT_NEAR(slopes[4], documented[4], 0.005);  // Counts: not rounded.
  EXPECT_NEAR(slopes[5], documented[5], 0.005);
  const std::string text = ScalingSlopesText(kSizes, DocsRun(), slopes);
  EXPECT_EQ(text.rfind("\nlog-log slope over N = 10000..990000", 0), 0u);
  EXPECT_NE(text.find("  sampled points:     0.46\n"), std::string::npos);
  EXPECT_NE(text.find("  finest-layer cells: 0.30\n"), std::string::npos);
  EXPECT_NE(text.find("solve against sampled points (time ∝ S^slope): 0.9"),
            std::string::npos);
}

TEST(ScalingTableText, ReproducesTheDocumentedRows) {
  const std::string table = ScalingTableText(DocsRun());
  EXPECT_NE(table.find("| 10000 | 0.6 | 0.3 | 18.7 | 20.5 | 3626 | 479 | 5 | "
                       "45 | 2.39 | 0.073 | ok |\n"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("| 990000 | 19.9 | 17.8 | 131.6 | 178.3 | 30097 | "
                       "2005 | 5 | 36 | 0.31 | 0.002 | ok |\n"),
            std::string::npos)
      << table;
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 7);
}

TEST(BrokenSolveLines, NameFailedAndOffSizesOnly) {
  std::vector<SizeResult> results = DocsRun();
  results[1].ok = false;
  results[1].termination = TerminationType::FAILURE;
  results[1].message = "too few points";
  results[3].ok = false;
  results[3].translation_error_m = 0.25;
  const std::vector<std::string> lines = BrokenSolveLines(results, 0.1, 0.5);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "N = 30000: registration FAILED: too few points");
  EXPECT_EQ(lines[1],
            "N = 300000: recovered motion off by 25.00 cm, 0.007 deg "
            "(tolerance 10.0 cm, 0.50 deg)");
  EXPECT_NE(ScalingTableText(results).find("| FAILED |"), std::string::npos);
  EXPECT_NE(ScalingTableText(results).find("| LARGE ERROR |"),
            std::string::npos);
}

TEST(WriteScalingCsv, WritesOneRowPerSize) {
  const std::string dir = testing::TestScratchDir();
  std::string error;
  ASSERT_TRUE(WriteScalingCsv(dir + "/scaling.csv", DocsRun(), &error))
      << error;
  std::ifstream in(dir + "/scaling.csv");
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[1],
            "10000,0.6,0.3,18.7,20.5,3626,479,5,45,CONVERGENCE,0.0239,0.073,1");
  EXPECT_FALSE(WriteScalingCsv("/nonexistent/scaling.csv", DocsRun(), &error));
  EXPECT_NE(error.find("/nonexistent/scaling.csv"), std::string::npos);

  if (std::system("gnuplot --version >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "gnuplot is not installed: scaling.png not tested";
  }
  ASSERT_TRUE(WriteScalingPlot("gnuplot",
                               dir,
                               "a title",
                               DocsRun(),
                               ScalingSlopes(kSizes, DocsRun()),
                               &error))
      << error;
  EXPECT_GT(std::filesystem::file_size(dir + "/scaling.png"), 1000u);
  std::ifstream script(dir + "/scaling.gp");
  std::stringstream text;
  text << script.rdbuf();
  EXPECT_NE(text.str().find("'solve (slope 0.44)'"), std::string::npos);
}

}  // namespace
}  // namespace mlndt
