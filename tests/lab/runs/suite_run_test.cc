// Loading, running and scoring suite data sets (lab/runs/suite_run.h) on
// the bundled koide3 and room pairs: the runs planned and their scans found
// (a missing folder or reference file named), the plan's lines, one result per
// planned run in order, a start 50 m off never right (nor reported
// CONVERGENCE), the score counting the same runs, and an unreadable scan
// refused with the data set's name.

#include "lab/runs/suite_run.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

SuitePlanOptions Plan() {
  SuitePlanOptions plan;
  plan.starts = {StartKind::IDENTITY, StartKind::OFFSETS};
  std::string error;
  // 50 m: far outside any basin of these scenes, so that the run is wrong.
  EXPECT_TRUE(ParseStartOffsets("x:50", &plan.offsets, &error)) << error;
  return plan;
}

LoadedSuiteDataset Load(const std::string& name,
                        size_t index,
                        const SuitePlanOptions& plan) {
  SuiteDataset dataset;
  dataset.name = name;
  dataset.dir = testing::BundledDataPath(name);
  LoadedSuiteDataset set;
  std::string error;
  EXPECT_TRUE(LoadSuiteDataset(dataset, index, plan, &set, &error)) << error;
  return set;
}

TEST(LoadSuiteDataset, PlansTheRunsAndFindsTheirScans) {
  const LoadedSuiteDataset set = Load("koide3", 3, Plan());
  EXPECT_EQ(set.dataset.name, "koide3");
  ASSERT_EQ(set.pairs.size(), 1u);
  ASSERT_EQ(set.runs.size(), 2u);  // Identity and x = 50 m.
  EXPECT_EQ(set.runs[0].dataset, 3u);
  EXPECT_EQ(set.runs[0].pair_key, "251370668_251371071");
  EXPECT_EQ(set.runs[1].start, "x=50");
  EXPECT_EQ(
      set.scan_paths,
      (std::map<int64_t, std::string>{
          {251370668, testing::BundledDataPath("koide3/251370668.pcd")},
          {251371071, testing::BundledDataPath("koide3/251371071.pcd")}}));
}

TEST(LoadSuiteDataset, NamesAMissingFolderOrReferenceFile) {
  SuiteDataset dataset;
  dataset.name = "missing";
  dataset.dir = testing::BundledDataPath("missing");
  LoadedSuiteDataset set;
  std::string error;
  EXPECT_FALSE(LoadSuiteDataset(dataset, 0, Plan(), &set, &error));
  EXPECT_EQ(error, dataset.dir + ": not a folder");
  // kitti/pcd holds scans but no reference_pairs.json.
  dataset.dir = testing::BundledDataPath("kitti/pcd");
  EXPECT_FALSE(LoadSuiteDataset(dataset, 0, Plan(), &set, &error));
  EXPECT_NE(error.find("reference_pairs.json"), std::string::npos) << error;
}

TEST(SuitePlanText, NamesEveryDataSetAndTheTotal) {
  const SuitePlanOptions plan = Plan();
  const std::vector<LoadedSuiteDataset> sets = {Load("koide3", 0, plan),
                                                Load("room", 1, plan)};
  EXPECT_EQ(SuitePlanText(sets),
            "koide3: " + sets[0].dataset.dir +
                ", 1 reference pairs, 2 runs on 2 scans, right within 0.2 m "
                "and 1 deg\n"
                "room: " +
                sets[1].dataset.dir +
                ", 1 reference pairs, 2 runs on 2 scans, right within 0.2 m "
                "and 1 deg\n"
                "4 runs\n\n");
}

TEST(RunSuite, RunsAndScoresEveryPlannedRun) {
  const SuitePlanOptions plan = Plan();
  const std::vector<LoadedSuiteDataset> sets = {Load("koide3", 0, plan),
                                                Load("room", 1, plan)};
  std::vector<ProgressEvent> events;
  ProgressFunction progress(
      [&](const ProgressEvent& e) { events.push_back(e); });
  std::vector<std::vector<SuiteRunResult>> results;
  std::string error;
  ASSERT_TRUE(RunSuite(MatcherOptions(), sets, &progress, &results, &error))
      << error;
  ASSERT_EQ(results.size(), 2u);
  // The runs numbered across the suite, each led by its data set's name.
  ASSERT_EQ(events.size(), 4u);
  for (size_t k = 0; k < events.size(); ++k) {
    EXPECT_EQ(events[k].index, k);
    EXPECT_EQ(events[k].done, k + 1);
    EXPECT_EQ(events[k].total, 4u);
    const std::string name = k < 2 ? "koide3 " : "room ";
    EXPECT_EQ(events[k].status.rfind(name, 0), 0u) << events[k].status;
  }
  size_t right = 0, wrong_convergence = 0;
  for (size_t d = 0; d < sets.size(); ++d) {
    ASSERT_EQ(results[d].size(), sets[d].runs.size());
    for (size_t k = 0; k < results[d].size(); ++k) {
      const SuiteOutcome& outcome = results[d][k].outcome;
      EXPECT_EQ(outcome.dataset, d);
      EXPECT_EQ(outcome.kind, sets[d].runs[k].kind);
      right += outcome.right;
      wrong_convergence +=
          !outcome.right && outcome.termination == TerminationType::CONVERGENCE;
    }
    // Identity: koide3's and room's starts are within the basin.
    EXPECT_TRUE(results[d][0].outcome.right) << sets[d].dataset.name;
    EXPECT_FALSE(results[d][1].outcome.right) << sets[d].dataset.name;
  }
  EXPECT_EQ(right, 2u);
  EXPECT_EQ(wrong_convergence, 0u);

  size_t runs = 0;
  const SuiteScore score = ScoreLoadedSuite(sets, results, plan, 0.9, &runs);
  EXPECT_EQ(runs, 4u);
  EXPECT_EQ(score.datasets, (std::vector<std::string>{"koide3", "room"}));
  EXPECT_EQ(score.confusion.total(), 4u);
  EXPECT_EQ(score.confusion.total_right(), right);
  ASSERT_EQ(score.reach.size(), 1u);  // The one offset, x = 50 m.
  EXPECT_EQ(score.reach[0].all.runs, 2u);
  EXPECT_EQ(score.reach[0].all.right, 0u);
}

TEST(RunSuite, NamesTheDataSetOfAnUnreadableScan) {
  const SuitePlanOptions plan = Plan();
  std::vector<LoadedSuiteDataset> sets = {Load("room", 0, plan)};
  sets[0].scan_paths.begin()->second = "/nonexistent/scan.pcd";
  std::vector<std::vector<SuiteRunResult>> results;
  std::string error;
  EXPECT_FALSE(RunSuite(MatcherOptions(), sets, nullptr, &results, &error));
  EXPECT_EQ(error.rfind("room: ", 0), 0u) << error;
  EXPECT_NE(error.find("/nonexistent/scan.pcd"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
