// Runs mlndt_experiments --quick on the bundled data (kitti, room, koide3)
// and checks the report: every section of the paper's Section 5 is there,
// every table row the report prints is the row of its CSV, the run count
// matches runs.csv, every figure exists, and the defaults reach further
// than the paper preset on the bundled KITTI pairs (issue 15).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/run_tool.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;
using testing::ReadWholeFile;
using testing::ShellQuote;

// One CSV line into cells ("..." with "" for a quote).
std::vector<std::string> CsvCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        cells.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      cells.emplace_back();
    } else {
      cells.back() += ch;
    }
  }
  return cells;
}

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(ReadWholeFile(path));
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) rows.push_back(CsvCells(line));
  }
  return rows;
}

// The report of one quick run, shared by the checks below (one TEST: the
// run takes ~20 s, and ctest runs every TEST in its own process).
struct QuickReport {
  std::string dir;
  std::string report;
};

void CheckSections(const QuickReport& q);
void CheckTablesAreCsvRows(const QuickReport& q);
void CheckRunCount(const QuickReport& q);
void CheckFigures(const QuickReport& q);
void CheckKittiReach(const QuickReport& q);

TEST(MlndtExperiments, QuickReportIsCompleteAndConsistent) {
  QuickReport q;
  q.dir = testing::ScratchPath("quick");
  fs::remove_all(q.dir);
  const bool plots = std::system("gnuplot --version >/dev/null 2>&1") == 0;
  const testing::ToolRun run = testing::RunTool(
      "mlndt_experiments",
      "--quick --data_dir=" + ShellQuote(testing::BundledDataPath("")) +
          " --out=" + ShellQuote(q.dir) + (plots ? "" : " --plots=false"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  q.report = ReadWholeFile(q.dir + "/README_RESULTS.md");
  ASSERT_FALSE(q.report.empty());
  CheckSections(q);
  CheckTablesAreCsvRows(q);
  CheckRunCount(q);
  if (plots) CheckFigures(q);
  CheckKittiReach(q);
}

void CheckSections(const QuickReport& q) {
  SCOPED_TRACE("sections");
  for (const char* heading : {"## Headline: paper preset against defaults",
                              "## Configurations",
                              "## Fig. 10:",
                              "## Fig. 11:",
                              "## Fig. 12:",
                              "## Fig. 13:",
                              "## Section 5.1:",
                              "## Table 2 and Fig. 14:",
                              "## Table 3 and Fig. 15:",
                              "## Table 4 and Fig. 16:",
                              "## Table 5:",
                              "## Table 6 and Fig. 18:",
                              "## Table 7:",
                              "## Fig. 17:",
                              "## Table 8:",
                              "## Table 9:",
                              "## Sampling fraction sweep:",
                              "## Not reproduced here"}) {
    EXPECT_NE(q.report.find(heading), std::string::npos) << heading;
  }
  // Accuracy is against the references, and no caveat text is canned.
  EXPECT_EQ(q.report.find("Ground-truth caveat"), std::string::npos);
  // The ablation table names every step.
  for (const char* step : {"| `objective.loss` | NONE | CAUCHY | +Cauchy loss",
                           "+nearest-cell scoring",
                           "+our schedule"}) {
    EXPECT_NE(q.report.find(step), std::string::npos) << step;
  }
  // The data sets that are not bundled are said to be missing.
  EXPECT_NE(q.report.find("(their rows are absent): mulran, 3dtk."),
            std::string::npos);
}

void CheckTablesAreCsvRows(const QuickReport& q) {
  SCOPED_TRACE("tables");
  for (const char* name : {"headline",
                           "table2",
                           "table3",
                           "table4",
                           "table5",
                           "table6",
                           "table7",
                           "table8",
                           "table9",
                           "sampling"}) {
    const auto rows = ReadCsv(q.dir + "/csv/" + name + ".csv");
    ASSERT_GE(rows.size(), 2u) << name;
    for (size_t r = 1; r < rows.size(); ++r) {
      std::string line = "|";
      for (const std::string& cell : rows[r]) line += " " + cell + " |";
      EXPECT_NE(q.report.find(line + "\n"), std::string::npos)
          << name << ".csv row " << r << ": " << line;
    }
  }
}

void CheckRunCount(const QuickReport& q) {
  SCOPED_TRACE("run count");
  const auto runs = ReadCsv(q.dir + "/csv/runs.csv");
  ASSERT_GT(runs.size(), 100u);
  EXPECT_NE(q.report.find(std::to_string(runs.size() - 1) + " registrations"),
            std::string::npos);
}

void CheckFigures(const QuickReport& q) {
  SCOPED_TRACE("figures");
  size_t figures = 0;
  for (size_t at = q.report.find("](figures/"); at != std::string::npos;
       at = q.report.find("](figures/", at + 1)) {
    const size_t end = q.report.find(')', at);
    const std::string png = q.report.substr(at + 2, end - at - 2);
    EXPECT_GT(fs::file_size(q.dir + "/" + png), 1000u) << png;
    ++figures;
  }
  EXPECT_EQ(figures, 12u);  // Figs. 10-18, two reach plots, the sweep.
}

// The finding: the paper preset reaches no long-range offset on
// KITTI under the strict rule; the defaults do.
void CheckKittiReach(const QuickReport& q) {
  SCOPED_TRACE("kitti reach");
  double paper = -1, defaults = -1;
  for (const auto& row : ReadCsv(q.dir + "/csv/reach.csv")) {
    if (row.size() < 3 || row[0] != "kitti") continue;
    if (row[1] == "paper") paper = std::stod(row[2]);
    if (row[1] == "defaults") defaults = std::stod(row[2]);
  }
  ASSERT_GE(paper, 0.0);
  EXPECT_GE(defaults, 5.0);
  EXPECT_GT(defaults, paper);
}

}  // namespace
}  // namespace mlndt
