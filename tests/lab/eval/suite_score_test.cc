// Scoring a suite: the along-track error's sign, right/wrong against the
// tolerance, the confusion counts and the precision/recall arithmetic on
// hand-made results, the per-start, accuracy and reach tables, the
// targets, and the printed tables' cells.

#include "lab/eval/suite_score.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lab/eval/suite_report.h"
#include "mlndt/common/pose.h"
#include "tests/testing/text_table.h"

namespace mlndt {
namespace {

Isometry3d Pose(double tx, double ty, double tz, double yaw_deg) {
  return PoseVectorToIsometry(PoseVectorFromDegrees(tx, ty, tz, 0, 0, yaw_deg));
}

TEST(AlongTrackErrorM, IsNegativeShortOfTheReference) {
  // The reference moves 2 m along x.
  EXPECT_NEAR(
      AlongTrackErrorM(Pose(2, 0, 0, 0), Pose(1.9, 0.05, 0, 0)), -0.1, 1e-12);
  EXPECT_NEAR(
      AlongTrackErrorM(Pose(2, 0, 0, 0), Pose(2.1, -0.3, 0.2, 5)), 0.1, 1e-12);
  // Along its own direction, whatever the rotation: 3 m along -y, the
  // estimate 2.5 m.
  EXPECT_NEAR(
      AlongTrackErrorM(Pose(0, -3, 0, 40), Pose(0, -2.5, 0, 40)), -0.5, 1e-12);
  EXPECT_NEAR(
      AlongTrackErrorM(Pose(3, 4, 0, 0), Pose(3.6, 4.8, 0, 0)), 1.0, 1e-12);
  // Sideways errors do not count.
  EXPECT_NEAR(AlongTrackErrorM(Pose(3, 4, 0, 0), Pose(3 - 0.8, 4 + 0.6, 0, 0)),
              0.0,
              1e-12);
  EXPECT_TRUE(
      std::isnan(AlongTrackErrorM(Pose(0, 0, 0, 30), Pose(1, 0, 0, 0))));
}

TEST(ScoreSuiteRun, RightIsStrictlyWithinBothTolerances) {
  SuiteRun run;
  run.dataset = 2;
  run.kind = StartKind::OFFSETS;
  run.offset_index = 4;
  run.reference_from_input = Pose(2, 0, 0, 0);
  const SuccessCriterion criterion{0.1, 1.0};
  SuiteOutcome o = ScoreSuiteRun(
      run, criterion, TerminationType::LOW_QUALITY, Pose(2.05, 0, 0, 0.5), 12);
  EXPECT_TRUE(o.right);
  EXPECT_EQ(o.dataset, 2u);
  EXPECT_EQ(o.kind, StartKind::OFFSETS);
  EXPECT_EQ(o.offset_index, 4);
  EXPECT_EQ(o.termination, TerminationType::LOW_QUALITY);
  EXPECT_NEAR(o.error.translation_m, 0.05, 1e-12);
  EXPECT_NEAR(o.error.rotation_deg(), 0.5, 1e-9);
  EXPECT_NEAR(o.along_track_m, 0.05, 1e-12);
  EXPECT_EQ(o.time_ms, 12);
  o = ScoreSuiteRun(
      run, criterion, TerminationType::CONVERGENCE, Pose(2.15, 0, 0, 0), 1);
  EXPECT_FALSE(o.right);  // 15 cm > 10 cm.
  o = ScoreSuiteRun(
      run, criterion, TerminationType::CONVERGENCE, Pose(2, 0, 0, 1.5), 1);
  EXPECT_FALSE(o.right);  // 1.5° > 1°.
}

// On a pair the scene leaves free (a corridor along x), DEGENERATE is the
// right answer wherever the pose ends, and CONVERGENCE is wrong even at
// the truth.
TEST(ScoreSuiteRun, AFreePairIsRightOnlyWhenDegenerate) {
  SuiteRun run;
  run.reference_from_input = Pose(2, 0, 0, 0);
  Vector6d along_x = Vector6d::Zero();
  along_x(0) = 1.0;
  run.free_directions = {along_x};
  const SuccessCriterion criterion{0.1, 1.0};
  SuiteOutcome o = ScoreSuiteRun(
      run, criterion, TerminationType::DEGENERATE, Pose(5, 0, 0, 0), 1);
  EXPECT_TRUE(o.free);
  EXPECT_TRUE(o.right);
  o = ScoreSuiteRun(
      run, criterion, TerminationType::CONVERGENCE, Pose(2, 0, 0, 0), 1);
  EXPECT_FALSE(o.right);
  for (const TerminationType type : {TerminationType::NO_CONVERGENCE,
                                     TerminationType::LOW_QUALITY,
                                     TerminationType::FAILURE}) {
    EXPECT_FALSE(
        ScoreSuiteRun(run, criterion, type, Pose(2, 0, 0, 0), 1).right);
  }
  // A wrong CONVERGENCE in the confusion table; no accuracy from free runs.
  const std::vector<SuiteOutcome> outcomes = {
      o,
      ScoreSuiteRun(
          run, criterion, TerminationType::DEGENERATE, Pose(5, 0, 0, 0), 1)};
  const ConfusionTable table = CountConfusion(outcomes);
  EXPECT_EQ(table.Count(false, TerminationType::CONVERGENCE), 1u);
  EXPECT_EQ(table.Count(true, TerminationType::DEGENERATE), 1u);
  EXPECT_EQ(table.Precision(), 0.0);
  const SuiteScore score = ScoreSuite(
      {"corridor"}, {StartKind::IDENTITY}, {}, {SuiteSkips()}, outcomes, 0.9);
  ASSERT_EQ(score.accuracy.size(), 1u);
  EXPECT_EQ(score.accuracy[0].right, 0u);
  // Without free directions the same run is scored by its pose.
  run.free_directions.clear();
  EXPECT_TRUE(
      ScoreSuiteRun(
          run, criterion, TerminationType::CONVERGENCE, Pose(2, 0, 0, 0), 1)
          .right);
}

TEST(AllTerminationTypes, ListsEveryValueInOrder) {
  const std::vector<TerminationType> types = AllTerminationTypes();
  ASSERT_GE(types.size(), 5u);
  EXPECT_EQ(types[0], TerminationType::CONVERGENCE);
  EXPECT_EQ(types[1], TerminationType::NO_CONVERGENCE);
  EXPECT_EQ(types[2], TerminationType::FAILURE);
  EXPECT_EQ(types[3], TerminationType::LOW_QUALITY);
  EXPECT_EQ(types[4], TerminationType::DEGENERATE);
  for (const TerminationType type : types) {
    EXPECT_STRNE(TerminationTypeToString(type), "UNKNOWN");
  }
}

SuiteOutcome Outcome(TerminationType type, bool right) {
  SuiteOutcome o;
  o.termination = type;
  o.right = right;
  return o;
}

void Add(TerminationType type,
         bool right,
         int n,
         std::vector<SuiteOutcome>* out) {
  for (int k = 0; k < n; ++k) out->push_back(Outcome(type, right));
}

// 6 right and 2 wrong CONVERGENCE, 2 right and 1 wrong NO_CONVERGENCE,
// 4 right and 4 wrong LOW_QUALITY, 1 wrong FAILURE: 12 of 20 right.
std::vector<SuiteOutcome> HandMade() {
  std::vector<SuiteOutcome> o;
  Add(TerminationType::CONVERGENCE, true, 6, &o);
  Add(TerminationType::CONVERGENCE, false, 2, &o);
  Add(TerminationType::NO_CONVERGENCE, true, 2, &o);
  Add(TerminationType::NO_CONVERGENCE, false, 1, &o);
  Add(TerminationType::LOW_QUALITY, true, 4, &o);
  Add(TerminationType::LOW_QUALITY, false, 4, &o);
  Add(TerminationType::FAILURE, false, 1, &o);
  return o;
}

TEST(CountConfusion, CountsAndShares) {
  const ConfusionTable c = CountConfusion(HandMade());
  EXPECT_EQ(c.Count(true, TerminationType::CONVERGENCE), 6u);
  EXPECT_EQ(c.Count(false, TerminationType::CONVERGENCE), 2u);
  EXPECT_EQ(c.Count(true, TerminationType::NO_CONVERGENCE), 2u);
  EXPECT_EQ(c.Count(false, TerminationType::NO_CONVERGENCE), 1u);
  EXPECT_EQ(c.Count(true, TerminationType::LOW_QUALITY), 4u);
  EXPECT_EQ(c.Count(false, TerminationType::LOW_QUALITY), 4u);
  EXPECT_EQ(c.Count(true, TerminationType::FAILURE), 0u);
  EXPECT_EQ(c.Count(false, TerminationType::FAILURE), 1u);
  EXPECT_EQ(c.Count(false, TerminationType::DEGENERATE), 0u);
  EXPECT_EQ(c.Reported(TerminationType::CONVERGENCE), 8u);
  EXPECT_EQ(c.total(), 20u);
  EXPECT_EQ(c.total_right(), 12u);
  EXPECT_DOUBLE_EQ(c.Precision(), 6.0 / 8.0);  // Of CONVERGENCE, right.
  EXPECT_DOUBLE_EQ(c.Recall(), 6.0 / 12.0);    // Of right, CONVERGENCE.
  EXPECT_DOUBLE_EQ(c.UsablePrecision(), 8.0 / 11.0);
  EXPECT_DOUBLE_EQ(c.UsableRecall(), 8.0 / 12.0);
  EXPECT_DOUBLE_EQ(c.Success(), 12.0 / 20.0);
}

TEST(CountConfusion, SharesOfNothingAreUndefined) {
  ConfusionTable c = CountConfusion({});
  EXPECT_TRUE(std::isnan(c.Precision()));
  EXPECT_TRUE(std::isnan(c.Recall()));
  EXPECT_TRUE(std::isnan(c.Success()));
  // Only wrong LOW_QUALITY: nothing reported CONVERGENCE, nothing right.
  c = CountConfusion({Outcome(TerminationType::LOW_QUALITY, false)});
  EXPECT_TRUE(std::isnan(c.Precision()));
  EXPECT_TRUE(std::isnan(c.UsablePrecision()));
  EXPECT_TRUE(std::isnan(c.Recall()));
  EXPECT_DOUBLE_EQ(c.Success(), 0.0);
}

// Two data sets, identity and offsets (x=1, x=2, x=3 and yaw=10).
struct Scored {
  std::vector<StartOffset> offsets;
  std::vector<SuiteOutcome> outcomes;
  SuiteScore score;
};

SuiteOutcome Run(size_t dataset,
                 StartKind kind,
                 int offset,
                 TerminationType type,
                 bool right,
                 double error_m,
                 double along_m,
                 double time_ms) {
  SuiteOutcome o = Outcome(type, right);
  o.dataset = dataset;
  o.kind = kind;
  o.offset_index = offset;
  o.error.translation_m = error_m;
  o.error.rotation_rad = 0.1 * error_m * kDegToRad;
  o.along_track_m = along_m;
  o.time_ms = time_ms;
  return o;
}

Scored MakeScored() {
  Scored s;
  std::string error;
  EXPECT_TRUE(ParseStartOffsets("x:1,2,3;yaw:10", &s.offsets, &error));
  const auto C = TerminationType::CONVERGENCE;
  const auto L = TerminationType::LOW_QUALITY;
  const auto I = StartKind::IDENTITY;
  const auto O = StartKind::OFFSETS;
  s.outcomes = {
      Run(0, I, -1, C, true, 0.03, -0.03, 10),
      Run(0, I, -1, C, true, 0.04, NAN, 30),
      Run(0, I, -1, L, false, 5.0, 4.0, 20),
      Run(1, I, -1, C, false, 0.5, -0.5, 40),
      // Data set 0: x=1 2/2, x=2 1/2, x=3 2/2, yaw=10 0/1.
      Run(0, O, 0, C, true, 0.01, 0, 1),
      Run(0, O, 0, C, true, 0.01, 0, 1),
      Run(0, O, 1, C, true, 0.01, 0, 1),
      Run(0, O, 1, L, false, 3, 0, 1),
      Run(0, O, 2, C, true, 0.01, 0, 1),
      Run(0, O, 2, C, true, 0.01, 0, 1),
      Run(0, O, 3, L, false, 3, 0, 1),
      // Data set 1: x=1 1/1, x=2 1/1, yaw=10 1/1; no x=3 run.
      Run(1, O, 0, C, true, 0.01, 0, 1),
      Run(1, O, 1, C, true, 0.01, 0, 1),
      Run(1, O, 3, C, true, 0.01, 0, 1),
  };
  SuiteSkips skips0 = {{StartKind::PRIOR, 3}};
  s.score = ScoreSuite({"a", "b"},
                       {I, StartKind::PRIOR, O},
                       s.offsets,
                       {skips0, {}},
                       s.outcomes,
                       0.9);
  return s;
}

TEST(ScoreSuite, RowsPerDataSetAndStart) {
  const Scored s = MakeScored();
  const std::vector<SuiteStartRow>& rows = s.score.by_start;
  // a/identity, a/prior (skipped only), a/offsets, b/identity, b/offsets.
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].dataset, 0u);
  EXPECT_EQ(rows[0].kind, StartKind::IDENTITY);
  EXPECT_EQ(rows[0].runs, 3u);
  EXPECT_EQ(rows[0].right, 2u);
  EXPECT_EQ(rows[0].convergence, 2u);
  EXPECT_EQ(rows[0].wrong_convergence, 0u);
  EXPECT_EQ(rows[1].kind, StartKind::PRIOR);
  EXPECT_EQ(rows[1].runs, 0u);
  EXPECT_EQ(rows[1].skipped_pairs, 3u);
  EXPECT_EQ(rows[2].kind, StartKind::OFFSETS);
  EXPECT_EQ(rows[2].runs, 7u);
  EXPECT_EQ(rows[2].right, 5u);
  EXPECT_EQ(rows[3].dataset, 1u);
  EXPECT_EQ(rows[3].runs, 1u);
  EXPECT_EQ(rows[3].right, 0u);
  EXPECT_EQ(rows[3].wrong_convergence, 1u);  // CONVERGENCE, 50 cm off.
  EXPECT_EQ(rows[4].runs, 3u);
  EXPECT_EQ(s.score.confusion.total(), s.outcomes.size());
}

TEST(ScoreSuite, AccuracyOfTheRightRuns) {
  const Scored s = MakeScored();
  ASSERT_EQ(s.score.accuracy.size(), 2u);  // a/identity, b/identity.
  const SuiteAccuracyRow& a = s.score.accuracy[0];
  EXPECT_EQ(a.right, 2u);
  EXPECT_NEAR(
      a.rms_translation_m, std::sqrt((0.03 * 0.03 + 0.04 * 0.04) / 2), 1e-12);
  EXPECT_NEAR(a.rms_rotation_deg,
              std::sqrt((0.003 * 0.003 + 0.004 * 0.004) / 2),
              1e-12);
  // The NaN along-track error is left out; the wrong run is not counted.
  EXPECT_NEAR(a.mean_along_track_m, -0.03, 1e-12);
  EXPECT_NEAR(a.median_time_ms, 20.0, 1e-12);
  const SuiteAccuracyRow& b = s.score.accuracy[1];
  EXPECT_EQ(b.right, 0u);
  EXPECT_TRUE(std::isnan(b.mean_along_track_m));
}

TEST(ScoreSuite, ReachIsTheLastOffsetBeforeTheFirstMiss) {
  const Scored s = MakeScored();
  ASSERT_EQ(s.score.reach.size(), 4u);
  EXPECT_EQ(s.score.reach[1].per_dataset[0].runs, 2u);
  EXPECT_EQ(s.score.reach[1].per_dataset[0].right, 1u);
  EXPECT_EQ(s.score.reach[1].all.runs, 3u);
  EXPECT_EQ(s.score.reach[1].all.right, 2u);
  EXPECT_EQ(s.score.reach[2].per_dataset[1].runs, 0u);
  ASSERT_EQ(s.score.family_reach.size(), 2u);
  const SuiteFamilyReach& x = s.score.family_reach[0];
  EXPECT_EQ(x.family, "x");
  // a: x=2 misses (50 %), so x=3's 100 % does not extend the reach.
  EXPECT_EQ(x.per_dataset[0], 0);
  // b: x=1, x=2 right, x=3 not run.
  EXPECT_EQ(x.per_dataset[1], 1);
  EXPECT_EQ(x.all, 0);  // x=2: 2 of 3.
  const SuiteFamilyReach& yaw = s.score.family_reach[1];
  EXPECT_EQ(yaw.per_dataset[0], -1);  // The first offset misses.
  EXPECT_EQ(yaw.per_dataset[1], 3);
  EXPECT_EQ(yaw.all, -1);  // 1 of 2: none.
}

TEST(SuiteTargets, ParseAndMiss) {
  std::vector<SuiteTarget> targets;
  std::string error;
  ASSERT_TRUE(ParseSuiteTargets(
      "precision:0.7,recall:0.6,success:0.98,usable_recall:0.5",
      &targets,
      &error))
      << error;
  ASSERT_EQ(targets.size(), 4u);
  EXPECT_EQ(targets[0].measure, SuiteMeasure::PRECISION);
  EXPECT_EQ(targets[2].minimum, 0.98);
  const ConfusionTable c = CountConfusion(HandMade());
  // precision 0.75 >= 0.7, recall 0.5 < 0.6, success 0.6 < 0.98,
  // usable recall 0.667 >= 0.5.
  const std::vector<std::string> missed = MissedSuiteTargets(c, targets);
  ASSERT_EQ(missed.size(), 2u);
  EXPECT_EQ(missed[0], "recall 0.5 < 0.6");
  EXPECT_EQ(missed[1], "success 0.6 < 0.98");
  // Undefined misses.
  const std::vector<std::string> none = MissedSuiteTargets(
      CountConfusion({}), {{SuiteMeasure::USABLE_PRECISION, 0.0}});
  ASSERT_EQ(none.size(), 1u);
  EXPECT_NE(none[0].find("undefined"), std::string::npos);
  for (const char* bad : {"",
                          "precision",
                          "precision:",
                          "precision:1.5",
                          "precision:x",
                          "accuracy:0.5",
                          "recall:0.5,recall:0.6",
                          "recall:0.5,"}) {
    EXPECT_FALSE(ParseSuiteTargets(bad, &targets, &error)) << bad;
  }
}

// The row of `table` whose first cell is `name`.
std::vector<std::string> TableRow(const std::string& table,
                                  const std::string& name) {
  for (const std::string& line : testing::Split(table, '\n')) {
    const std::vector<std::string> cells = testing::TableCells(line);
    if (!cells.empty() && cells[0] == name) return cells;
  }
  return {};
}

TEST(FormatSuiteReport, TablesHoldTheCounts) {
  const std::string confusion =
      FormatSuiteConfusion(CountConfusion(HandMade()));
  EXPECT_EQ(TableRow(confusion, "pose"),
            (std::vector<std::string>{"pose",
                                      "CONVERGENCE",
                                      "NO_CONVERGENCE",
                                      "FAILURE",
                                      "LOW_QUALITY",
                                      "DEGENERATE",
                                      "total"}));
  EXPECT_EQ(TableRow(confusion, "right"),
            (std::vector<std::string>{"right", "6", "2", "0", "4", "0", "12"}));
  EXPECT_EQ(TableRow(confusion, "wrong"),
            (std::vector<std::string>{"wrong", "2", "1", "1", "4", "0", "8"}));
  EXPECT_EQ(TableRow(confusion, "total"),
            (std::vector<std::string>{"total", "8", "3", "1", "8", "0", "20"}));
  EXPECT_NE(confusion.find("precision 0.7500 (6 of 8"), std::string::npos)
      << confusion;
  EXPECT_NE(confusion.find("recall 0.5000 (6 of 12"), std::string::npos);
  EXPECT_NE(confusion.find("precision 0.7273 (8 of 11"), std::string::npos);
  EXPECT_NE(confusion.find("success: 60.0 % (12 of 20"), std::string::npos);

  const Scored s = MakeScored();
  const std::string report = FormatSuiteReport(s.score);
  const std::vector<std::string> starts = TableRow(report, "b");
  ASSERT_EQ(starts.size(), 8u) << report;
  EXPECT_EQ(starts[1], "identity");
  EXPECT_EQ(starts[2], "1");
  EXPECT_EQ(starts[6], "1");  // Wrong but CONVERGENCE.
  EXPECT_EQ(TableRow(report, "x=2"),
            (std::vector<std::string>{
                "x=2", "50.0 (1/2)", "100.0 (1/1)", "66.7 (2/3)"}));
  EXPECT_EQ(
      TableRow(report, "x=3"),
      (std::vector<std::string>{"x=3", "100.0 (2/2)", "–", "100.0 (2/2)"}));
  EXPECT_EQ(TableRow(report, "x"),
            (std::vector<std::string>{"x", "1", "2", "1"}));
  EXPECT_EQ(TableRow(report, "yaw"),
            (std::vector<std::string>{"yaw", "none", "10", "none"}));
}

}  // namespace
}  // namespace mlndt
