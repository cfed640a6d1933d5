// WriteBenchPlot: the data file holds every set's points sorted by time
// with the Pareto front flagged (worked out by hand below), the script
// draws one panel per set, the PNG is written; bad paths and a missing
// gnuplot are errors.

#include "lab/bench/bench_plot.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

// koide3: C (30 ms, 3 cm) is beaten by B (20 ms, 2 cm); A and B are on the
// front. kitti: F (40 ms, 2 m) is beaten by D (5 ms, 1 m); D and E are on
// it. Given out of time order.
std::vector<BenchPlotPoint> Points() {
  return {{"koide3", "C", 30.0, 0.03},
          {"kitti", "E", 50.0, 0.01},
          {"koide3", "A", 10.0, 0.05},
          {"kitti", "F", 40.0, 2.0},
          {"koide3", "B", 20.0, 0.02},
          {"kitti", "D", 5.0, 1.0}};
}

TEST(WriteBenchPlot, WritesTheSetsSortedByTimeWithTheParetoFront) {
  if (!GnuplotRuns()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string png = testing::ScratchPath("bench.png");
  std::string error;
  ASSERT_TRUE(WriteBenchPlot("gnuplot", png, Points(), &error)) << error;
  EXPECT_EQ(ReadText(png + ".dat"),
            "# koide3\n# time_ms error_m pareto label\n"
            "10 0.05 1 \"A\"\n20 0.02 1 \"B\"\n30 0.03 0 \"C\"\n\n\n"
            "# kitti\n# time_ms error_m pareto label\n"
            "5 1 1 \"D\"\n40 2 0 \"F\"\n50 0.01 1 \"E\"\n\n\n");
  const std::string script = ReadText(png + ".gp");
  EXPECT_NE(script.find("set multiplot layout 2,1"), std::string::npos);
  EXPECT_NE(script.find("koide3: one point per configuration"),
            std::string::npos);
  EXPECT_NE(script.find(" index 1 "), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
}

TEST(WriteBenchPlot, RefusesAnUnwritablePathOrAMissingGnuplot) {
  std::string error;
  EXPECT_FALSE(WriteBenchPlot(
      "gnuplot", "/nonexistent/folder/bench.png", Points(), &error));
  EXPECT_NE(error.find("/nonexistent/folder/bench.png.dat"), std::string::npos)
      << error;
  error.clear();
  EXPECT_FALSE(WriteBenchPlot("/nonexistent/gnuplot",
                              testing::ScratchPath("bench.png"),
                              Points(),
                              &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mlndt
