// The odometry on the shared Livox Avia sequence (fastlio_avia_hku_2_sequence,
// hand-held, 250 keyframes), scored step by step against its LIO prior
// (FAST-LIO2 + SC-PGO, good to ~2 cm from step to step): a scan reported
// CONVERGENCE must not be a wrong pose.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lab/eval/scan_times.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "mlndt/odometry/run_odometry.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// A step is wrong beyond these (scripts/step_errors.py's defaults).
constexpr double kStepToleranceM = 0.2;
constexpr double kStepToleranceDeg = 2.0;

std::string ScanName(size_t index) {
  std::string name = std::to_string(index);
  return std::string(6 - name.size(), '0') + name + ".pcd";
}

struct StepScore {
  size_t wrong_convergence = 0;  // CONVERGENCE, but off the prior.
  size_t right_convergence = 0;  // CONVERGENCE and within the tolerance.
  size_t wrong_flagged = 0;      // Off the prior, not CONVERGENCE.
  std::vector<size_t> wrong_convergence_scans;
};

// Scores scan k's motion from the last scan with a registered pose (not a
// fallback) against the prior's, so that a scan after a fallback is judged
// by its own pose and not by the stand-in before it.
StepScore ScoreSteps(const std::vector<OdometryResult>& results,
                     const std::vector<Isometry3d>& prior) {
  StepScore score;
  size_t last = 0;
  for (size_t k = 1; k < results.size(); ++k) {
    if (results[k].fallback) continue;
    const Isometry3d estimated = results[last].world_from_sensor.inverse() *
                                 results[k].world_from_sensor;
    const Isometry3d reference = prior[last].inverse() * prior[k];
    const bool wrong =
        TranslationErrorM(estimated, reference) > kStepToleranceM ||
        RotationErrorRad(estimated, reference) * kRadToDeg > kStepToleranceDeg;
    const bool convergence =
        results[k].termination == TerminationType::CONVERGENCE;
    if (wrong && convergence) {
      ++score.wrong_convergence;
      score.wrong_convergence_scans.push_back(k);
    } else if (wrong) {
      ++score.wrong_flagged;
    } else if (convergence) {
      ++score.right_convergence;
    }
    last = k;
  }
  return score;
}

// The odometry from scratch on scans [first, first + count) of the sequence
// (the first of them the origin), and the prior's poses of those scans.
void RunStretch(const std::string& data_dir,
                size_t first,
                size_t count,
                std::vector<OdometryResult>* results,
                OdometrySummary* summary,
                std::vector<Isometry3d>* prior,
                const OdometryOptions& options = OdometryOptions(),
                const std::string& poses = "prior_poses.txt") {
  const std::string sequence = data_dir + "/fastlio_avia_hku_2_sequence";
  std::vector<double> stamps;
  std::vector<Isometry3d> all_prior;
  std::string error;
  ASSERT_TRUE(ReadScanTimes(sequence + "/times.txt", &stamps, &error)) << error;
  ASSERT_TRUE(ReadKittiPoses(sequence + "/" + poses, &all_prior, &error))
      << error;
  ASSERT_GE(stamps.size(), first + count);
  ASSERT_GE(all_prior.size(), first + count);
  prior->assign(all_prior.begin() + first, all_prior.begin() + first + count);
  const OdometryScanLoader load = [&](size_t i,
                                      PointCloud* cloud,
                                      std::vector<double>* times,
                                      double* stamp_s,
                                      std::string* load_error) {
    times->clear();
    *stamp_s = stamps.at(first + i);
    return ReadPointCloud(
        sequence + "/pcd/" + ScanName(first + i), cloud, nullptr, load_error);
  };
  ASSERT_TRUE(RunOdometry(options, count, load, {}, results, summary, &error))
      << error;
  ASSERT_EQ(results->size(), count);
}

// Scans 160-249 of the sequence, the first of them the origin: the walk
// back along the corridor, with one step the registration gets wrong (scan
// 173). Measured (docs/odometry.md), with the odometry's probe of weak
// directions (OdometryOptions::max_flatness 0.8): scans 173-175 are
// DEGENERATE, the map restarts at 176, 84 of the 89 steps CONVERGENCE and
// within 0.2 m / 2 deg of the prior, 4 fallbacks (without the probe: 173 is
// NO_CONVERGENCE, 88 right, no fallback); the confirmation from beyond the
// pose takes one right step from CONVERGENCE (83), the last-scan check
// (last_scan_check.h) one more (82). No step off the prior may be
// reported CONVERGENCE, and most are still CONVERGENCE and right.
TEST(OdometryLivox, NoWrongStepIsReportedConvergenceOnTheCorridorStretch) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  constexpr size_t kFirst = 160;
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::vector<Isometry3d> prior;
  ASSERT_NO_FATAL_FAILURE(
      RunStretch(data_dir, kFirst, 90, &results, &summary, &prior));

  const StepScore score = ScoreSteps(results, prior);
  EXPECT_EQ(score.wrong_convergence, 0u)
      << "first wrong step reported CONVERGENCE: scan "
      << kFirst + score.wrong_convergence_scans.front();
  EXPECT_GE(score.right_convergence, 75u);  // Measured 82 of 89.
  EXPECT_LE(summary.fallbacks, 10u);        // Measured 4.
}

// Scans 0-89 from a fresh start: without the confirmation of CONVERGENCE
// from beyond the pose (confirm_pose.h) two wrong steps are reported
// CONVERGENCE (scans 86 and 87, 0.38 and 0.77 m off the prior: corrections
// of 0.24 and 0.38 m, more than half the prediction's uncertainty); with it
// (the default) none, 81 of the 89 CONVERGENCE and right (85 without), 1
// fallback; since the guess check over a subset (826d2dd) and with the
// last-scan check 76 right (84 without the confirmation), 3 fallbacks. The
// confirmation changes verdicts only: the poses, fallbacks and keyframes of the
// two runs are the same.
TEST(OdometryLivox, TheConfirmationKeepsWrongStepsFromConvergence) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::vector<Isometry3d> prior;
  ASSERT_NO_FATAL_FAILURE(
      RunStretch(data_dir, 0, 90, &results, &summary, &prior));
  const StepScore score = ScoreSteps(results, prior);
  EXPECT_EQ(score.wrong_convergence, 0u)
      << "first wrong step reported CONVERGENCE: scan "
      << score.wrong_convergence_scans.front();
  EXPECT_GE(score.right_convergence, 70u);  // Measured 76 of 89.
  EXPECT_LE(summary.fallbacks, 5u);         // Measured 3.

  OdometryOptions unconfirmed;
  unconfirmed.confirmation.enabled = false;
  std::vector<OdometryResult> unconfirmed_results;
  OdometrySummary unconfirmed_summary;
  ASSERT_NO_FATAL_FAILURE(RunStretch(data_dir,
                                     0,
                                     90,
                                     &unconfirmed_results,
                                     &unconfirmed_summary,
                                     &prior,
                                     unconfirmed));
  EXPECT_GE(ScoreSteps(unconfirmed_results, prior).wrong_convergence, 1u)
      << "measured UNCONF wrong CONVERGENCE without the confirmation";
}

// Scans 60-109 from a fresh start: the far corner, where the sensor looks
// around in small steps and the registrations slide along directions the
// scans barely constrain. Without the probe of weak directions 21 of the 49
// steps were wrong and reported CONVERGENCE (24 CONVERGENCE and right, 6
// fallbacks); with it 5 wrong CONVERGENCE, 23 right, 23 fallbacks; with the
// confirmation from beyond the pose too 3 wrong, 21 right; with the
// last-scan check too (the odometry's defaults) none, 21 right, 21
// fallbacks (the test below). Here the bound says the probe catches most.
TEST(OdometryLivox, TheProbeOfWeakDirectionsCatchesMostSlidesInTheFarCorner) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  constexpr size_t kFirst = 60;
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::vector<Isometry3d> prior;
  ASSERT_NO_FATAL_FAILURE(
      RunStretch(data_dir, kFirst, 50, &results, &summary, &prior));

  const StepScore score = ScoreSteps(results, prior);
  EXPECT_LE(score.wrong_convergence, 10u);  // Measured 0 (21 without).
  EXPECT_GE(score.right_convergence, 18u);  // Measured 21 (24).
  EXPECT_LE(summary.fallbacks, 30u);        // Measured 21 (6).
}

// Scans 60-109 from a fresh start (the far corner, as the test above):
// with the confirmation from beyond the pose alone three wrong steps are
// reported CONVERGENCE (the second run returned to each pose: consistent
// minima of a local map that holds keyframes at wrong, unconfirmed poses);
// registered onto the last registered scan alone from the same prediction
// they end farther than 0.1 m or 2 deg from their poses, so the last-scan
// check (last_scan_check.h, the default) reports them NO_CONVERGENCE.
// Measured: none wrong, 21 of the 49 CONVERGENCE and right, 21 fallbacks,
// with the check and without it (where 3 are wrong). The check changes
// verdicts only: the poses, fallbacks and keyframes of the two runs are the
// same.
TEST(OdometryLivox, TheLastScanCheckKeepsWrongStepsFromConvergence) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  constexpr size_t kFirst = 60;
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::vector<Isometry3d> prior;
  ASSERT_NO_FATAL_FAILURE(
      RunStretch(data_dir, kFirst, 50, &results, &summary, &prior));
  const StepScore score = ScoreSteps(results, prior);
  EXPECT_EQ(score.wrong_convergence, 0u)
      << "first wrong step reported CONVERGENCE: scan "
      << kFirst + score.wrong_convergence_scans.front();
  EXPECT_GE(score.right_convergence, 18u);  // Measured 21 of 49.
  EXPECT_LE(summary.fallbacks, 30u);        // Measured 21.

  OdometryOptions unchecked;
  unchecked.confirmation.check_last_scan = false;
  std::vector<OdometryResult> unchecked_results;
  OdometrySummary unchecked_summary;
  ASSERT_NO_FATAL_FAILURE(RunStretch(data_dir,
                                     kFirst,
                                     50,
                                     &unchecked_results,
                                     &unchecked_summary,
                                     &prior,
                                     unchecked));
  EXPECT_GE(ScoreSteps(unchecked_results, prior).wrong_convergence, 1u)
      << "measured UNCHECKED wrong CONVERGENCE without the last-scan check";
}

// The whole loop (250 scans, 55.8 m), scored against FAST-LIO2's odometry
// (odom_poses.txt, the better of the two pose files over the loop: the
// data's README). Before issue 42 the local map restarted five times at a
// prediction and the loop ended 9.2 m, 53.5 deg from where the reference
// has it (16.5 % of the path); now no scan restarts the map, every scan
// without a registered pose is interpolated between registered ones, none
// reported CONVERGENCE is off its reference step, and the loop ends within
// 0.5 m and 2 deg (measured END).
TEST(OdometryLivox, TheWholeLoopIsKeptWithoutRestarts) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  std::vector<Isometry3d> reference;
  ASSERT_NO_FATAL_FAILURE(RunStretch(data_dir,
                                     0,
                                     250,
                                     &results,
                                     &summary,
                                     &reference,
                                     OdometryOptions(),
                                     "odom_poses.txt"));
  const StepScore score = ScoreSteps(results, reference);
  EXPECT_EQ(score.wrong_convergence, 0u)
      << "first wrong step reported CONVERGENCE: scan "
      << score.wrong_convergence_scans.front();
  EXPECT_GE(score.right_convergence, 150u);  // Measured RIGHT.
  EXPECT_EQ(summary.interpolated, summary.fallbacks);
  EXPECT_GT(summary.recovered, 0u);
  for (const OdometryResult& r : results) {
    EXPECT_EQ(r.fallback, r.termination != TerminationType::CONVERGENCE);
    EXPECT_EQ(r.fallback, r.interpolated) << "scan " << r.index;
  }
  const Isometry3d estimated_loop =
      results.front().world_from_sensor.inverse() *
      results.back().world_from_sensor;
  const Isometry3d reference_loop =
      reference.front().inverse() * reference.back();
  EXPECT_LT(TranslationErrorM(estimated_loop, reference_loop), 0.5);
  EXPECT_LT(RotationErrorRad(estimated_loop, reference_loop) * kRadToDeg, 2.0);
}

}  // namespace
}  // namespace mlndt