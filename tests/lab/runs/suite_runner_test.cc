// RunSuiteDataset: runs a plan in order on a synthetic sequence, scores
// each run against its reference, passes a start's uncertainty to ML-NDT
// only, and reports an unreadable scan as an error naming the file.

#include "lab/runs/suite_runner.h"

#include <gtest/gtest.h>

#include "mlndt/common/pose.h"
#include "tests/testing/synthetic_sequence.h"

namespace mlndt {
namespace {

TEST(SuiteRunOptions, SetsTheStartsUncertaintyForMlNdtOnly) {
  MatcherOptions options;
  options.mlndt.initial_uncertainty = {true, 9.0, 90.0};
  SuiteRun run;
  // No uncertainty of its own: the options' stays.
  MatcherOptions o = SuiteRunOptions(options, run);
  EXPECT_TRUE(o.mlndt.initial_uncertainty.given);
  EXPECT_EQ(o.mlndt.initial_uncertainty.translation_m, 9.0);
  run.uncertainty = {true, 0.5, 5.0};
  o = SuiteRunOptions(options, run);
  EXPECT_TRUE(o.mlndt.initial_uncertainty.given);
  EXPECT_EQ(o.mlndt.initial_uncertainty.translation_m, 0.5);
  EXPECT_EQ(o.mlndt.initial_uncertainty.rotation_deg, 5.0);
  options = MatcherOptions();
  options.method = Method::NDT;
  o = SuiteRunOptions(options, run);
  EXPECT_FALSE(o.mlndt.initial_uncertainty.given);
}

TEST(RunSuiteDataset, RunsThePlanInOrderAndScoresEachRun) {
  const testing::SyntheticSequence sequence = testing::WriteSyntheticSequence(
      "suite_runner", 3, 20000, testing::SmallStepMotion());
  std::map<std::string, ReferencePair> pairs;
  for (const auto& [i, j] : {std::pair<int, int>{0, 1}, {1, 2}, {0, 2}}) {
    ReferencePair pair;
    pair.reference_index = i;
    pair.input_index = j;
    pair.reference_from_input = sequence.world_from_scan[size_t(i)].inverse() *
                                sequence.world_from_scan[size_t(j)];
    pairs[ReferencePairKey(i, j)] = pair;
  }
  SuitePlanOptions plan;
  plan.starts = {StartKind::IDENTITY, StartKind::OFFSETS};
  std::string error;
  // 50 m: far outside the scene's basin, so that it is wrong.
  ASSERT_TRUE(ParseStartOffsets("x:0.3,50", &plan.offsets, &error));
  SuiteSkips skips;
  const std::vector<SuiteRun> runs =
      PlanDatasetRuns(plan, 1, "synthetic", pairs, &skips);
  ASSERT_EQ(runs.size(), 9u);
  const std::map<int64_t, std::string> scans = {
      {0, sequence.paths[0]}, {1, sequence.paths[1]}, {2, sequence.paths[2]}};

  MatcherOptions options;
  options.mlndt.retry.yaw_seeds_deg.clear();
  std::vector<std::string> seen;
  ProgressFunction progress([&](const ProgressEvent& e) {
    EXPECT_EQ(e.done, seen.size() + 1);
    EXPECT_EQ(e.total, runs.size());
    seen.push_back(e.status);
  });
  std::vector<SuiteRunResult> results;
  ASSERT_TRUE(RunSuiteDataset(options,
                              SuccessCriterion{0.05, 1.0},
                              scans,
                              runs,
                              &progress,
                              &results,
                              &error))
      << error;
  ASSERT_EQ(results.size(), runs.size());
  ASSERT_EQ(seen.size(), runs.size());
  EXPECT_EQ(seen.front(), "0_1 identity: CONVERGENCE right");
  EXPECT_EQ(seen.back().rfind("1_2 x=50: ", 0), 0u) << seen.back();
  EXPECT_NE(seen.back().find(" wrong"), std::string::npos) << seen.back();
  size_t built = 0;
  for (size_t k = 0; k < runs.size(); ++k) {
    const SuiteRunResult& r = results[k];
    EXPECT_EQ(r.outcome.dataset, 1u);
    EXPECT_EQ(r.outcome.kind, runs[k].kind);
    EXPECT_EQ(r.outcome.offset_index, runs[k].offset_index);
    EXPECT_NEAR(r.outcome.error.translation_m,
                TranslationErrorM(runs[k].reference_from_input,
                                  r.registration.reference_from_input),
                1e-12);
    EXPECT_GT(r.registration.quality.points, 0u);
    EXPECT_GE(r.registration.attempts, 1);
    built += r.times.map_ms > 0.0 ? 1 : 0;
    if (runs[k].start != "x=50") {
      EXPECT_TRUE(r.outcome.right) << seen[k] << ": " << r.registration.message;
      EXPECT_EQ(r.outcome.termination, TerminationType::CONVERGENCE) << seen[k];
    } else {
      EXPECT_FALSE(r.outcome.right) << seen[k];
    }
  }
  EXPECT_EQ(built, 2u);  // Maps of scans 0 and 1, each built once.

  // An unreadable scan is an error naming its file.
  std::map<int64_t, std::string> broken = scans;
  broken[2] = sequence.paths[2] + ".missing.pcd";
  results.clear();
  EXPECT_FALSE(RunSuiteDataset(
      options, SuccessCriterion(), broken, runs, nullptr, &results, &error));
  EXPECT_NE(error.find(".missing.pcd"), std::string::npos) << error;
}

}  // namespace
}  // namespace mlndt
