#include "lab/eval/trajectory_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mlndt/common/pose.h"
#include "tests/testing/eigen_near.h"

namespace mlndt {
namespace {

using testing::EigenNear;

// A seeded random walk: steps of ~1 m with a few degrees of turn each, so
// that the positions span all three axes.
std::vector<Isometry3d> RandomWalk(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Isometry3d> poses = {Isometry3d::Identity()};
  for (int k = 1; k < n; ++k) {
    const Vector6d step = PoseVectorFromDegrees(1.0 + 0.2 * normal(rng),
                                                0.3 * normal(rng),
                                                0.3 * normal(rng),
                                                5 * normal(rng),
                                                5 * normal(rng),
                                                10 * normal(rng));
    poses.push_back(poses.back() * PoseVectorToIsometry(step));
  }
  return poses;
}

const Isometry3d kWorldOffset =
    PoseVectorToIsometry(PoseVectorFromDegrees(20, -7, 3, 10, -30, 120));

TEST(ComputeAte, Se3RecoversTheTransformAndTheNoise) {
  const std::vector<Isometry3d> truth = RandomWalk(300, 1);
  std::mt19937 rng(2);
  const double sigma = 0.05;  // Per axis [m].
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Isometry3d> estimate;
  for (const Isometry3d& pose : truth) {
    Isometry3d e = kWorldOffset * pose;
    e.translation() += Vector3d(noise(rng), noise(rng), noise(rng));
    estimate.push_back(e);
  }
  AteSummary ate;
  std::string error;
  ASSERT_TRUE(ComputeAte(AteOptions(), truth, estimate, &ate, &error)) << error;
  const Isometry3d expected = kWorldOffset.inverse();
  EXPECT_TRUE(
      EigenNear(ate.reference_from_estimate.rotation, expected.linear(), 2e-3));
  EXPECT_TRUE(EigenNear(
      ate.reference_from_estimate.translation, expected.translation(), 0.05));
  EXPECT_EQ(ate.reference_from_estimate.scale, 1.0);
  // 3-D noise: RMSE sqrt(3) sigma, a little less after fitting 6 dof.
  EXPECT_NEAR(ate.rmse_m, std::sqrt(3.0) * sigma, 0.1 * sigma);
  ASSERT_EQ(ate.errors_m.size(), truth.size());
  EXPECT_LT(ate.errors.mean, ate.rmse_m);
  EXPECT_LT(ate.errors.median, ate.errors.max);
  EXPECT_EQ(ate.errors.count, truth.size());
}

TEST(ComputeAte, Sim3RecoversTheScaleThatSe3CannotAbsorb) {
  const std::vector<Isometry3d> truth = RandomWalk(200, 4);
  const double scale = 0.6;  // The estimate is 0.6 x too small.
  std::vector<Isometry3d> estimate;
  for (const Isometry3d& pose : truth) {
    Isometry3d e = kWorldOffset * pose;
    e.translation() *= scale;
    estimate.push_back(e);
  }
  AteOptions options;
  options.alignment = TrajectoryAlignment::SIM3;
  AteSummary sim3, se3;
  std::string error;
  ASSERT_TRUE(ComputeAte(options, truth, estimate, &sim3, &error)) << error;
  EXPECT_NEAR(sim3.reference_from_estimate.scale, 1.0 / scale, 1e-9);
  EXPECT_TRUE(EigenNear(sim3.reference_from_estimate.rotation,
                        kWorldOffset.linear().transpose(),
                        1e-9));
  EXPECT_LT(sim3.rmse_m, 1e-9);
  options.alignment = TrajectoryAlignment::SE3;
  ASSERT_TRUE(ComputeAte(options, truth, estimate, &se3, &error)) << error;
  EXPECT_GT(se3.rmse_m, 1.0);
}

TEST(ComputeAte, NoneAndFirstPoseAlignments) {
  const std::vector<Isometry3d> truth = RandomWalk(20, 6);
  // Offsets of known length per pose, in the world frame.
  std::vector<Isometry3d> shifted = truth;
  std::vector<double> lengths;
  for (size_t k = 0; k < truth.size(); ++k) {
    const double length = 0.01 * static_cast<double>(k);
    shifted[k].translation() += length * Vector3d(0.6, 0.0, 0.8);
    lengths.push_back(length);
  }
  AteOptions options;
  options.alignment = TrajectoryAlignment::NONE;
  AteSummary ate;
  std::string error;
  ASSERT_TRUE(ComputeAte(options, truth, shifted, &ate, &error)) << error;
  for (size_t k = 0; k < truth.size(); ++k)
    EXPECT_NEAR(ate.errors_m[k], lengths[k], 1e-12);
  EXPECT_NEAR(ate.errors.max, 0.19, 1e-12);
  EXPECT_NEAR(ate.errors.median, 0.095, 1e-12);
  double squares = 0.0;
  for (double l : lengths) squares += l * l;
  EXPECT_NEAR(ate.rmse_m, std::sqrt(squares / lengths.size()), 1e-12);

  // FIRST_POSE maps estimate_0 onto truth_0: a rigidly moved copy has no
  // error at all, while NONE sees the whole offset. (The truth does not
  // start at the identity, so that the order of the product matters.)
  const Isometry3d start =
      PoseVectorToIsometry(PoseVectorFromDegrees(-4, 9, 1, 40, 5, -60));
  std::vector<Isometry3d> started, moved;
  for (const Isometry3d& pose : truth) {
    started.push_back(start * pose);
    moved.push_back(kWorldOffset * start * pose);
  }
  options.alignment = TrajectoryAlignment::FIRST_POSE;
  ASSERT_TRUE(ComputeAte(options, started, moved, &ate, &error)) << error;
  EXPECT_LT(ate.rmse_m, 1e-9);
  EXPECT_TRUE(EigenNear(ate.reference_from_estimate.rotation,
                        kWorldOffset.linear().transpose(),
                        1e-12));
  options.alignment = TrajectoryAlignment::NONE;
  ASSERT_TRUE(ComputeAte(options, started, moved, &ate, &error)) << error;
  EXPECT_GT(ate.rmse_m, 1.0);
}

TEST(ComputeAte, Failures) {
  const std::vector<Isometry3d> truth = RandomWalk(5, 7);
  AteSummary ate;
  std::string error;
  EXPECT_FALSE(ComputeAte(AteOptions(),
                          truth,
                          std::vector<Isometry3d>(4, Isometry3d::Identity()),
                          &ate,
                          &error));
  EXPECT_NE(error.find("5 reference poses but 4"), std::string::npos) << error;
  EXPECT_FALSE(ComputeAte(AteOptions(), {}, {}, &ate, &error));
  const std::vector<Isometry3d> two(truth.begin(), truth.begin() + 2);
  EXPECT_FALSE(ComputeAte(AteOptions(), two, two, &ate, &error));
  EXPECT_NE(error.find("at least 3"), std::string::npos) << error;
}

TEST(TrajectoryAlignment, StringConversions) {
  for (TrajectoryAlignment a : {TrajectoryAlignment::NONE,
                                TrajectoryAlignment::FIRST_POSE,
                                TrajectoryAlignment::SE3,
                                TrajectoryAlignment::SIM3}) {
    TrajectoryAlignment parsed;
    ASSERT_TRUE(
        StringToTrajectoryAlignment(TrajectoryAlignmentToString(a), &parsed));
    EXPECT_EQ(parsed, a);
  }
  TrajectoryAlignment parsed;
  ASSERT_TRUE(StringToTrajectoryAlignment("sim3", &parsed));
  EXPECT_EQ(parsed, TrajectoryAlignment::SIM3);
  EXPECT_FALSE(StringToTrajectoryAlignment("umeyama", &parsed));
  // The names, as the hand-written function gave them (from the table now).
  EXPECT_STREQ(TrajectoryAlignmentToString(TrajectoryAlignment::FIRST_POSE),
               "FIRST_POSE");
  EXPECT_STREQ(TrajectoryAlignmentToString(static_cast<TrajectoryAlignment>(9)),
               "UNKNOWN");
  ASSERT_TRUE(StringToTrajectoryAlignment("First_Pose", &parsed));
  EXPECT_EQ(parsed, TrajectoryAlignment::FIRST_POSE);
}

// est_{k+1} = est_k (truth_k^-1 truth_{k+1}) D: every relative motion of the
// estimate is the true one followed by the same error D, so the RPE with
// delta = 1 is D for every pair, whatever the world frame of the estimate.
TEST(ComputeRpe, ConstantPerStepErrorIsThatError) {
  const std::vector<Isometry3d> truth = RandomWalk(50, 8);
  const Isometry3d d =
      PoseVectorToIsometry(PoseVectorFromDegrees(0.03, -0.04, 0.0, 0.5, 0, 0));
  std::vector<Isometry3d> estimate = {kWorldOffset};
  for (size_t k = 0; k + 1 < truth.size(); ++k) {
    estimate.push_back(estimate.back() * truth[k].inverse() * truth[k + 1] * d);
  }
  RpeSummary rpe;
  std::string error;
  ASSERT_TRUE(ComputeRpe(RpeOptions(), truth, estimate, &rpe, &error)) << error;
  EXPECT_EQ(rpe.translation_m.count, truth.size() - 1);
  EXPECT_NEAR(rpe.translation_m.mean, 0.05, 1e-9);
  EXPECT_NEAR(rpe.translation_m.max, 0.05, 1e-9);
  EXPECT_NEAR(rpe.translation_m.min, 0.05, 1e-9);
  EXPECT_NEAR(rpe.translation_rmse_m, 0.05, 1e-9);
  EXPECT_NEAR(rpe.rotation_deg.mean, 0.5, 1e-6);
  EXPECT_NEAR(rpe.rotation_deg.max, 0.5, 1e-6);
  EXPECT_NEAR(rpe.rotation_rmse_deg, 0.5, 1e-6);

  // delta = 2: pairs (k, k+2), one fewer; errors compose, not constant.
  RpeOptions two;
  two.delta = 2;
  ASSERT_TRUE(ComputeRpe(two, truth, estimate, &rpe, &error)) << error;
  EXPECT_EQ(rpe.translation_m.count, truth.size() - 2);
  EXPECT_NEAR(rpe.rotation_deg.max, 1.0, 0.05);
}

// The translation error is |t(Q) - t(P)| (TranslationErrorM), which does not
// depend on how orthonormal R(Q) is; |t(Q^-1 P)| would, by 1e-4 here.
TEST(ComputeRpe, TranslationIsTheDifferenceOfTheRelativeTranslations) {
  std::vector<Isometry3d> truth = RandomWalk(3, 10);
  truth[1].linear() *= 1.0 + 1e-4;  // A rotation rounded badly in a file.
  std::vector<Isometry3d> estimate = truth;
  estimate[2].translation() += Vector3d(0.3, -0.2, 0.1);
  RpeSummary rpe;
  std::string error;
  ASSERT_TRUE(ComputeRpe(RpeOptions(), truth, estimate, &rpe, &error));
  const Isometry3d q = truth[1].inverse() * truth[2];
  const Isometry3d p = estimate[1].inverse() * estimate[2];
  EXPECT_NEAR(
      rpe.translation_m.max, (q.translation() - p.translation()).norm(), 1e-12);
  EXPECT_GT(
      std::abs(rpe.translation_m.max - (q.inverse() * p).translation().norm()),
      1e-6);
}

TEST(ComputeRpe, Failures) {
  const std::vector<Isometry3d> truth = RandomWalk(3, 9);
  RpeSummary rpe;
  std::string error;
  RpeOptions options;
  options.delta = 0;
  EXPECT_FALSE(ComputeRpe(options, truth, truth, &rpe, &error));
  EXPECT_NE(error.find("delta 0 < 1"), std::string::npos) << error;
  options.delta = 3;
  EXPECT_FALSE(ComputeRpe(options, truth, truth, &rpe, &error));
  EXPECT_NE(error.find("3 poses"), std::string::npos) << error;
  const std::vector<Isometry3d> two(truth.begin(), truth.begin() + 2);
  EXPECT_FALSE(ComputeRpe(RpeOptions(), truth, two, &rpe, &error));
}

}  // namespace
}  // namespace mlndt
