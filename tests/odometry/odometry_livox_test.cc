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
// by its own pose and not by the stand-in before it. A local-map restart is
// a declared discontinuity (the trajectory jumps there, flagged): the scans
// after it are judged from the restart scan, whose map they register onto.
StepScore ScoreSteps(const std::vector<OdometryResult>& results,
                     const std::vector<Isometry3d>& prior) {
  StepScore score;
  size_t last = 0;
  for (size_t k = 1; k < results.size(); ++k) {
    if (results[k].map_restarted) {
      last = k;
      continue;
    }
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

// Scans 160-249 of the sequence, the first of them the odometry's origin:
// the walk back along the corridor, with one step the registration gets
// wrong (scan 173, reported NO_CONVERGENCE; measured: 88 of the 89 steps
// CONVERGENCE and within 0.2 m / 2 deg of the prior, no fallback; with the
// weak-direction probe of the verdict branch 0add305, scans 173-175 are
// DEGENERATE, the map restarts at 176, 84 CONVERGENCE and right, 4
// fallbacks). No step off the prior may be reported CONVERGENCE, and most
// are still CONVERGENCE and right.
TEST(OdometryLivox, NoWrongStepIsReportedConvergenceOnTheCorridorStretch) {
  MLNDT_REQUIRE_SHARED_DATA(data_dir);
  const std::string sequence = data_dir + "/fastlio_avia_hku_2_sequence";
  constexpr size_t kFirst = 160;
  constexpr size_t kCount = 90;
  std::vector<double> stamps;
  std::vector<Isometry3d> all_prior;
  std::string error;
  ASSERT_TRUE(ReadScanTimes(sequence + "/times.txt", &stamps, &error)) << error;
  ASSERT_TRUE(ReadKittiPoses(sequence + "/prior_poses.txt", &all_prior, &error))
      << error;
  ASSERT_GE(stamps.size(), kFirst + kCount);
  ASSERT_GE(all_prior.size(), kFirst + kCount);
  const std::vector<Isometry3d> prior(all_prior.begin() + kFirst,
                                      all_prior.begin() + kFirst + kCount);
  const OdometryScanLoader load = [&](size_t i,
                                      PointCloud* cloud,
                                      std::vector<double>* times,
                                      double* stamp_s,
                                      std::string* load_error) {
    times->clear();
    *stamp_s = stamps.at(kFirst + i);
    return ReadPointCloud(
        sequence + "/pcd/" + ScanName(kFirst + i), cloud, nullptr, load_error);
  };
  std::vector<OdometryResult> results;
  OdometrySummary summary;
  ASSERT_TRUE(RunOdometry(
      OdometryOptions(), kCount, load, {}, &results, &summary, &error))
      << error;
  ASSERT_EQ(results.size(), kCount);

  const StepScore score = ScoreSteps(results, prior);
  EXPECT_EQ(score.wrong_convergence, 0u)
      << "first wrong step reported CONVERGENCE: scan "
      << kFirst + score.wrong_convergence_scans.front();
  EXPECT_GE(score.right_convergence, 75u);  // Measured 88 (84) of 89.
  EXPECT_LE(summary.fallbacks, 10u);        // Measured 0 (4).
}

}  // namespace
}  // namespace mlndt
