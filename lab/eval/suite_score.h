#pragma once

// Scoring a registration suite (suite_plan.h): how right the results are
// (within the data set's tolerance of the reference) and how honest the
// verdicts are (the confusion of right/wrong against the TerminationType
// the registration reported). suite_report.h prints the tables.

#include <limits>
#include <string>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/eval/suite_plan.h"
#include "mlndt/common/types.h"

namespace mlndt {

// What the scoring reads of one run.
struct SuiteOutcome {
  size_t dataset = 0;
  StartKind kind = StartKind::IDENTITY;
  int offset_index = -1;  // OFFSETS: index into the suite's offsets.
  TerminationType termination = TerminationType::FAILURE;
  PoseError error;  // Of the estimate against the reference.
  // AlongTrackErrorM; NaN when the reference does not move.
  double along_track_m = std::numeric_limits<double>::quiet_NaN();
  // Within the data set's SuccessCriterion; on a pair the scene leaves
  // free (free below), reported DEGENERATE.
  bool right = false;
  // The pair has free directions (SuiteRun::free_directions): no pose is
  // right or wrong along them, the verdict DEGENERATE is the right answer
  // and every other verdict a wrong one (CONVERGENCE there is a wrong
  // CONVERGENCE).
  bool free = false;
  double time_ms = 0.0;  // The registration's time (map build excluded).
};

// The translation error's component along the reference's translation
// direction, in the reference frame: (t_estimate - t_reference) . u with
// u = t_reference / |t_reference|. Negative: the estimate stops short of
// the reference. NaN when |t_reference| < 1 mm.
double AlongTrackErrorM(const Isometry3d& reference,
                        const Isometry3d& estimate);

// Scores the estimate of `run` (its reference is run.reference_from_input):
// right when within `criterion` of the reference, or, when the run's pair
// has free directions, right exactly when `termination` is DEGENERATE.
SuiteOutcome ScoreSuiteRun(const SuiteRun& run,
                           const SuccessCriterion& criterion,
                           TerminationType termination,
                           const Isometry3d& estimate,
                           double time_ms);

// Every TerminationType value, in declaration order (the confusion table's
// columns; a value added to the enum shows up here).
std::vector<TerminationType> AllTerminationTypes();

// Right/wrong × TerminationType counts.
struct ConfusionTable {
  std::vector<TerminationType> types = AllTerminationTypes();
  std::vector<size_t> right = std::vector<size_t>(types.size(), 0);
  std::vector<size_t> wrong = std::vector<size_t>(types.size(), 0);

  size_t Count(bool is_right, TerminationType type) const;
  size_t total() const;
  size_t total_right() const;
  // Runs reported `type`, right and wrong.
  size_t Reported(TerminationType type) const;

  // The share of CONVERGENCE results that are right; NaN without one.
  double Precision() const;
  // The share of right results reported CONVERGENCE; NaN without one.
  double Recall() const;
  // The same for "usable" (CONVERGENCE or NO_CONVERGENCE).
  double UsablePrecision() const;
  double UsableRecall() const;
  // The share of right results; NaN without runs.
  double Success() const;
};

ConfusionTable CountConfusion(const std::vector<SuiteOutcome>& outcomes);

// One row per data set × start kind that ran or was skipped.
struct SuiteStartRow {
  size_t dataset = 0;
  StartKind kind = StartKind::IDENTITY;
  size_t runs = 0;
  size_t right = 0;
  size_t convergence = 0;        // Reported CONVERGENCE.
  size_t wrong_convergence = 0;  // Reported CONVERGENCE but wrong.
  size_t skipped_pairs = 0;      // Pairs the start did not apply to.
};

// Accuracy of the right runs of one data set × start kind (runs on free
// pairs left out: their pose is not determined along the free directions).
struct SuiteAccuracyRow {
  size_t dataset = 0;
  StartKind kind = StartKind::IDENTITY;
  size_t right = 0;
  double rms_translation_m = 0.0;
  double mean_along_track_m = 0.0;  // NaN when no right run has one.
  double rms_rotation_deg = 0.0;
  double median_time_ms = 0.0;
};

// Right runs out of runs.
struct SuiteShare {
  size_t runs = 0;
  size_t right = 0;
  // right / runs; NaN without runs.
  double share() const;
};

// One row of the reach table: an offset, per data set and over all.
struct SuiteReachRow {
  int offset_index = 0;
  std::vector<SuiteShare> per_dataset;
  SuiteShare all;
};

// The reach of one offset family: the last offset (in the order given)
// such that it and every offset before it in the family have at least the
// reach share right; -1 when the first misses it, -2 when there were no
// runs. Per data set and over all.
struct SuiteFamilyReach {
  std::string family;
  std::vector<int> per_dataset;  // Offset indices.
  int all = -2;
};

struct SuiteScore {
  std::vector<std::string> datasets;  // Names, in suite order.
  std::vector<StartOffset> offsets;
  double reach_share = 0.9;
  ConfusionTable confusion;
  std::vector<SuiteStartRow> by_start;         // Data set, then start order.
  std::vector<SuiteAccuracyRow> accuracy;      // IDENTITY and PRIOR rows.
  std::vector<SuiteReachRow> reach;            // One per offset, in order.
  std::vector<SuiteFamilyReach> family_reach;  // Families in first order.
};

// `skips` holds one entry per data set (PlanDatasetRuns' counts); `starts`
// the start kinds in the order they ran. reach_share in (0, 1].
SuiteScore ScoreSuite(const std::vector<std::string>& datasets,
                      const std::vector<StartKind>& starts,
                      const std::vector<StartOffset>& offsets,
                      const std::vector<SuiteSkips>& skips,
                      const std::vector<SuiteOutcome>& outcomes,
                      double reach_share);

// ---- Targets (CI-style checks) --------------------------------------------

enum class SuiteMeasure {
  SUCCESS,           // ConfusionTable::Success.
  PRECISION,         // ::Precision.
  RECALL,            // ::Recall.
  USABLE_PRECISION,  // ::UsablePrecision.
  USABLE_RECALL,     // ::UsableRecall.
};

// "success", "precision", "recall", "usable_precision", "usable_recall".
const char* SuiteMeasureToString(SuiteMeasure measure);
bool StringToSuiteMeasure(std::string value, SuiteMeasure* measure);

double SuiteMeasureValue(const ConfusionTable& confusion, SuiteMeasure measure);

struct SuiteTarget {
  SuiteMeasure measure = SuiteMeasure::SUCCESS;
  double minimum = 0.0;  // Met when the measure is >= this.
};

// Parses "precision:0.995,recall:0.97,success:0.98" (each minimum in
// [0, 1], each measure once); false with *error naming the bad item.
bool ParseSuiteTargets(const std::string& text,
                       std::vector<SuiteTarget>* targets,
                       std::string* error);

// One line per target missed, e.g. "precision 0.9812 < 0.995"; a measure
// that is undefined (NaN: nothing to take the share of) misses its target.
std::vector<std::string> MissedSuiteTargets(
    const ConfusionTable& confusion, const std::vector<SuiteTarget>& targets);

}  // namespace mlndt
