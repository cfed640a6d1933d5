// VerdictCounts on a real runs table: the termination column of the 180
// reach runs on 3DTK in results/experiments/csv/runs.csv (copied into
// tests/lab/eval/data/reach_3dtk_runs.csv, header and rows unchanged, so
// that regenerating the results does not move the expectations), counted
// by hand with
//   awk -F, 'NR>1{c[$8]++} END{for(k in c) print k, c[k]}' FILE
// -> CONVERGENCE 89, LOW_QUALITY 49, DEGENERATE 11, FAILURE 31.

#include "lab/eval/verdict_counts.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// The "termination" column of a runs.csv.
std::vector<std::string> TerminationColumn(const std::string& path) {
  std::ifstream in(path);
  std::string line, cell;
  std::vector<std::string> values;
  if (!std::getline(in, line)) return values;
  std::istringstream header(line);
  int column = -1;
  for (int k = 0; std::getline(header, cell, ','); ++k) {
    if (cell == "termination") column = k;
  }
  if (column < 0) return values;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    for (int k = 0; k <= column && std::getline(row, cell, ','); ++k) {
    }
    values.push_back(cell);
  }
  return values;
}

TEST(VerdictCounts, CountsARealRunsTableByVerdict) {
  const std::vector<std::string> terminations = TerminationColumn(
      testing::BundledDataPath("../tests/lab/eval/data/reach_3dtk_runs.csv"));
  ASSERT_EQ(terminations.size(), 180u);
  VerdictCounts counts;
  for (const std::string& name : terminations) {
    TerminationType type;
    ASSERT_TRUE(StringToTerminationType(name, &type)) << name;
    counts.Add(type);
  }
  EXPECT_EQ(counts.total(), 180u);
  EXPECT_EQ(counts.count(TerminationType::CONVERGENCE), 89u);
  EXPECT_EQ(counts.count(TerminationType::NO_CONVERGENCE), 0u);
  EXPECT_EQ(counts.count(TerminationType::LOW_QUALITY), 49u);
  EXPECT_EQ(counts.count(TerminationType::DEGENERATE), 11u);
  EXPECT_EQ(counts.count(TerminationType::FAILURE), 31u);
  // Usable: CONVERGENCE and NO_CONVERGENCE (IsUsableTermination).
  EXPECT_EQ(counts.usable(), 89u);
  EXPECT_EQ(counts.unusable(), 91u);
  EXPECT_EQ(counts.Line(),
            "CONVERGENCE 89, NO_CONVERGENCE 0, LOW_QUALITY 49, DEGENERATE 11, "
            "FAILURE 31");
}

TEST(VerdictCounts, NoConvergenceIsUsableAndUnknownValuesAreFailures) {
  VerdictCounts counts;
  EXPECT_EQ(counts.Line(),
            "CONVERGENCE 0, NO_CONVERGENCE 0, LOW_QUALITY 0, DEGENERATE 0, "
            "FAILURE 0");
  counts.Add(TerminationType::NO_CONVERGENCE);
  counts.Add(static_cast<TerminationType>(99));
  EXPECT_EQ(counts.total(), 2u);
  EXPECT_EQ(counts.usable(), 1u);
  EXPECT_EQ(counts.count(TerminationType::FAILURE), 1u);
  EXPECT_EQ(counts.count(static_cast<TerminationType>(99)), 1u);
}

TEST(VerdictCounts, ListsEveryVerdictOnceUsableFirst) {
  const auto& verdicts = VerdictCounts::Verdicts();
  ASSERT_EQ(verdicts.size(), 5u);
  EXPECT_EQ(verdicts[0], TerminationType::CONVERGENCE);
  EXPECT_EQ(verdicts[1], TerminationType::NO_CONVERGENCE);
  for (size_t k = 2; k < verdicts.size(); ++k) {
    EXPECT_FALSE(IsUsableTermination(verdicts[k]));
  }
}

}  // namespace
}  // namespace mlndt
