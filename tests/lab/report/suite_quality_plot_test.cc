// WriteSuiteQualityPlot: per right and wrong runs, the sorted values of the
// inlier fraction and the mean score with their cumulative shares (runs
// without a fit and non-finite values left out; an empty curve written as
// "nan nan"), the quality check's thresholds drawn only when given, the
// PNG written; a folder that cannot be made is an error.

#include "lab/report/suite_quality_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/scratch_dir.h"

namespace mlndt {
namespace {

bool GnuplotRuns() {
  return std::system("gnuplot --version >/dev/null 2>&1") == 0;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

SuiteRunResult Run(bool right, size_t points, double inliers, double distance) {
  SuiteRunResult r;
  r.outcome.right = right;
  r.registration.quality.points = points;
  r.registration.quality.inlier_fraction = inliers;
  r.registration.quality.median_distance = distance;
  return r;
}

// Two data sets; the wrong runs have no finite distance.
std::vector<std::vector<SuiteRunResult>> Results() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {{Run(true, 4000, 0.8, 2.0),
           Run(true, 0, 0.1, 9.0),  // No fit: left out.
           Run(false, 500, 0.2, nan)},
          {Run(true, 3000, 0.6, 4.0),
           Run(true, 3500, 0.7, 3.0),
           Run(false, 800, 0.1, nan)}};
}

TEST(WriteSuiteQualityPlot, WritesTheSortedCurvesOfRightAndWrongRuns) {
  if (!GnuplotRuns()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = testing::TestScratchDir();
  const QualityCheckOptions check;
  std::string error;
  ASSERT_TRUE(WriteSuiteQualityPlot("gnuplot", dir, Results(), &check, &error))
      << error;
  const std::string data = dir + "/plot_data/";
  EXPECT_EQ(ReadText(data + "inlier_fraction_right.txt"),
            "0.6 0.3333333333\n0.7 0.6666666667\n0.8 1\n");
  EXPECT_EQ(ReadText(data + "median_distance_right.txt"),
            "2 0.3333333333\n3 0.6666666667\n4 1\n");
  EXPECT_EQ(ReadText(data + "inlier_fraction_wrong.txt"), "0.1 0.5\n0.2 1\n");
  EXPECT_EQ(ReadText(data + "median_distance_wrong.txt"), "nan nan\n");
  const std::string script = ReadText(data + "quality.gp");
  EXPECT_NE(script.find("title 'right (3)'"), std::string::npos);
  EXPECT_NE(script.find("title 'wrong (0)'"), std::string::npos);
  EXPECT_NE(script.find("\nset arrow 1 from 0.1,"), std::string::npos);
  EXPECT_NE(script.find("\nset arrow 2 from 3.8,"), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(dir + "/quality.png"), 1000u);

  // NDT: no quality check, no threshold lines.
  ASSERT_TRUE(WriteSuiteQualityPlot("gnuplot", dir, Results(), nullptr, &error))
      << error;
  EXPECT_EQ(ReadText(data + "quality.gp").find("\nset arrow"),
            std::string::npos);
}

TEST(WriteSuiteQualityPlot, RefusesAFolderThatCannotBeMade) {
  const std::string file = testing::ScratchPath("not_a_folder");
  std::ofstream(file) << "x";
  std::string error;
  EXPECT_FALSE(
      WriteSuiteQualityPlot("gnuplot", file, Results(), nullptr, &error));
  EXPECT_NE(error.find("not_a_folder/plot_data"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
