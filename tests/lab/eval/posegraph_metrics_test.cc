// EvaluatePoseGraphAccuracy on the bundled KITTI trajectory (data/kitti,
// frames 0-7): an estimate in another world frame with known per-pose
// errors, against the ATE and RPE computed here from their definitions
// (first-pose alignment; consecutive relative motions).

#include "lab/eval/posegraph_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lab/eval/trajectory_io.h"
#include "mlndt/common/pose.h"
#include "tests/testing/kitti_bundle.h"

namespace mlndt {
namespace {

// Pose k's own error: 1 cm and 0.1 deg of yaw per index (none on pose 0).
Isometry3d PoseError(size_t k) {
  return PoseVectorToIsometry(
      PoseVectorFromDegrees(0.01 * k, 0.0, 0.0, 0.0, 0.0, 0.1 * k));
}

// estimate_k = G truth_k D_k: G a change of world frame (removed by the
// first-pose alignment since D_0 = I), D_k the pose's own error.
std::vector<Isometry3d> Estimate(const std::vector<Isometry3d>& truth) {
  const Isometry3d world_change = PoseVectorToIsometry(
      PoseVectorFromDegrees(10.0, -4.0, 1.0, 2.0, -3.0, 30.0));
  std::vector<Isometry3d> estimate;
  for (size_t k = 0; k < truth.size(); ++k) {
    estimate.push_back(world_change * truth[k] * PoseError(k));
  }
  return estimate;
}

TEST(EvaluatePoseGraphAccuracy, MatchesTheDefinitionsOnKitti) {
  const std::vector<Isometry3d> truth = testing::BundledKittiPoses();
  ASSERT_EQ(truth.size(), 8u);
  const std::vector<Isometry3d> estimate = Estimate(truth);
  // ATE: aligned_k = truth_0 estimate_0^-1 estimate_k.
  double sum_squares = 0.0;
  for (size_t k = 0; k < truth.size(); ++k) {
    const Isometry3d aligned = truth[0] * estimate[0].inverse() * estimate[k];
    sum_squares +=
        (aligned.translation() - truth[k].translation()).squaredNorm();
  }
  const double ate_m = std::sqrt(sum_squares / truth.size());
  // ... which is |t(D_k)| = 0.01 k: sqrt(0.01^2 (0 + 1 + ... + 49) / 8).
  EXPECT_NEAR(ate_m, 0.01 * std::sqrt(140.0 / 8.0), 1e-9);
  // RPE: mean over k of |t(Q) - t(P)| and angle(R(Q)^T R(P)).
  double rpe_translation_m = 0.0, rpe_rotation_deg = 0.0;
  for (size_t k = 0; k + 1 < truth.size(); ++k) {
    const Isometry3d q = truth[k].inverse() * truth[k + 1];
    const Isometry3d p = estimate[k].inverse() * estimate[k + 1];
    rpe_translation_m += (q.translation() - p.translation()).norm();
    rpe_rotation_deg +=
        Eigen::AngleAxisd(q.linear().transpose() * p.linear()).angle() * 180.0 /
        M_PI;
  }
  rpe_translation_m /= truth.size() - 1;
  rpe_rotation_deg /= truth.size() - 1;

  PoseGraphAccuracy accuracy;
  std::string error;
  ASSERT_TRUE(EvaluatePoseGraphAccuracy(estimate, truth, &accuracy, &error))
      << error;
  EXPECT_NEAR(accuracy.ate_m, ate_m, 1e-9);
  EXPECT_NEAR(accuracy.rpe_translation_m, rpe_translation_m, 1e-9);
  EXPECT_NEAR(accuracy.rpe_rotation_deg, rpe_rotation_deg, 1e-7);
  // Each step adds 0.1 deg of yaw: the relative rotations are 0.1 deg off.
  EXPECT_NEAR(accuracy.rpe_rotation_deg, 0.1, 2e-3);
}

TEST(EvaluatePoseGraphAccuracy, IsZeroForTheTruthInAnotherWorldFrame) {
  const std::vector<Isometry3d> truth = testing::BundledKittiPoses();
  const Isometry3d world_change =
      PoseVectorToIsometry(PoseVectorFromDegrees(5, 6, 7, 10, 20, 30));
  std::vector<Isometry3d> estimate;
  for (const Isometry3d& pose : truth) estimate.push_back(world_change * pose);
  PoseGraphAccuracy accuracy;
  std::string error;
  ASSERT_TRUE(EvaluatePoseGraphAccuracy(estimate, truth, &accuracy, &error));
  EXPECT_NEAR(accuracy.ate_m, 0.0, 1e-9);
  EXPECT_NEAR(accuracy.rpe_translation_m, 0.0, 1e-9);
  EXPECT_NEAR(accuracy.rpe_rotation_deg, 0.0, 1e-5);
}

TEST(EvaluatePoseGraphAccuracy, RefusesTrajectoriesThatDoNotMatch) {
  const std::vector<Isometry3d> truth = testing::BundledKittiPoses();
  std::vector<Isometry3d> shorter = truth;
  shorter.pop_back();
  PoseGraphAccuracy accuracy;
  std::string error;
  EXPECT_FALSE(EvaluatePoseGraphAccuracy(shorter, truth, &accuracy, &error));
  EXPECT_FALSE(error.empty());
  // One pose: no relative motion to take the RPE of.
  error.clear();
  EXPECT_FALSE(
      EvaluatePoseGraphAccuracy({truth[0]}, {truth[0]}, &accuracy, &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mlndt
