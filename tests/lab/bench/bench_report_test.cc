#include "lab/bench/bench_report.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

namespace mlndt {
namespace {

BenchRowStats Stats(std::vector<double> times, int successes) {
  BenchRowStats s;
  s.round_times_ms = times;
  s.round_align_ms = std::vector<double>(times.size(), 1.5);
  s.runs = static_cast<int>(times.size());
  s.converged = s.runs;
  s.successes = successes;
  s.mean_iterations = 12.0;
  s.mean_point_iterations = 34567.4;
  s.mean_score = 345.67;
  s.mean_translation_error_m = 0.01234;
  s.mean_rotation_error_deg = 0.2345;
  return s;
}

// One set, an lm configuration and PCL NDT.
BenchResult Result() {
  BenchResult result;
  BenchConfiguration c;
  c.backend = BackendType::LEVENBERG_MARQUARDT;
  result.num_configurations = 1;
  result.methods = {ConfigurationLabels(c), BenchMethodLabels()};
  result.methods[1].sampling = "voxel_grid_0.1";
  result.sets = {"koide3"};
  result.set_pairs = {1};
  result.stats = {{Stats({10.0, 20.0}, 2), Stats({200.0, 300.0}, 1)}};
  return result;
}

TEST(BenchReport, TableRowsWithThePclRatio) {
  const BenchResult result = Result();
  const std::vector<std::string> header = BenchTableHeader();
  const std::vector<std::string> ours = BenchTableRow(
      "koide3", result.methods[0], result.stats[0][0], &result.stats[0][1]);
  ASSERT_EQ(ours.size(), header.size());
  std::map<std::string, std::string> row;
  for (size_t c = 0; c < header.size(); ++c) row[header[c]] = ours[c];
  EXPECT_EQ(row["method"], "lm");
  EXPECT_EQ(row["sampling"], "gbs_1m");
  EXPECT_EQ(row["linear solver"], "-");  // Ceres only.
  EXPECT_EQ(row["time med [ms]"], "15.0");
  EXPECT_EQ(row["time min-max [ms]"], "10.0-20.0");
  EXPECT_EQ(row["point iters"], "34567");
  EXPECT_EQ(row["score"], "345.7");
  EXPECT_EQ(row["err_t [m]"], "0.0123");
  EXPECT_EQ(row["success"], "2/2 (100%)");
  EXPECT_EQ(row["nees mean/med"], "-/-");
  EXPECT_EQ(row["pcl/ours"], "17.50");  // Median of 20 and 15.
  const std::vector<std::string> pcl = BenchTableRow(
      "koide3", result.methods[1], result.stats[0][1], &result.stats[0][1]);
  EXPECT_EQ(pcl[2], "pcl_ndt");
  EXPECT_EQ(pcl.back(), "-");  // No ratio on PCL's own row.
}

TEST(BenchReport, CsvTextHasAHeaderAndOneRowPerSetAndMethod) {
  const std::string csv = BenchCsvText(Result());
  std::istringstream lines(csv);
  std::string header, lm, pcl, rest;
  std::getline(lines, header);
  std::getline(lines, lm);
  std::getline(lines, pcl);
  EXPECT_FALSE(std::getline(lines, rest));
  EXPECT_EQ(header + "\n", BenchCsvHeader());
  EXPECT_EQ(lm.rfind("koide3,current,mlndt,lm,gbs_1m,", 0), 0u) << lm;
  // pcl_time_median_ms and pcl_over_ours last.
  const std::string last = ",250,17.5";
  EXPECT_EQ(lm.substr(lm.size() - last.size()), last) << lm;
  EXPECT_EQ(pcl.rfind("koide3,,pcl_ndt,,voxel_grid_0.1,", 0), 0u) << pcl;
}

TEST(BenchReport, ReportTextNamesTheRoundsMethodsAndPclNotes) {
  BenchOptions options;
  options.rounds.repetitions = 2;
  const std::string text = BenchReportText(options, Result());
  EXPECT_EQ(text.rfind("mlndt_bench: 2 round(s); 1 configuration(s) + "
                       "pcl::NDT;",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("  koide3: 1 run(s) a round\n"), std::string::npos);
  EXPECT_NE(text.find("| koide3 | current  | lm "), std::string::npos) << text;
  EXPECT_NE(text.find("- koide3: pcl_ndt align() alone (without filtering "
                      "and setInputTarget): median 1.5 ms"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("- success: translation error < 0.2 m"),
            std::string::npos);
}

TEST(BenchReport, MarkdownTablePadsColumns) {
  EXPECT_EQ(MarkdownTable({{"a", "bb"}, {"ccc", "d"}}),
            "| a   | bb  |\n|-----|-----|\n| ccc | d   |\n");
}

TEST(BenchPareto, FrontPerSet) {
  const std::vector<BenchPlotPoint> points = {{"a", "fast", 1.0, 0.5},
                                              {"a", "accurate", 5.0, 0.1},
                                              {"a", "dominated", 6.0, 0.2},
                                              {"b", "alone", 9.0, 9.0}};
  EXPECT_EQ(ParetoFront(points), (std::vector<bool>{true, true, false, true}));
  const std::vector<BenchPlotPoint> plot = BenchPlotPoints(Result());
  ASSERT_EQ(plot.size(), 2u);
  EXPECT_EQ(plot[0].label, "lm cauchy@1.5 gbs_1m s1 t1");
  EXPECT_EQ(plot[0].time_ms, 15.0);
  EXPECT_EQ(plot[1].label, "pcl_ndt");
}

}  // namespace
}  // namespace mlndt
