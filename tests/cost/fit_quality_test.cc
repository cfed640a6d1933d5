#include "mlndt/cost/fit_quality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/testing/objective.h"

namespace mlndt {
namespace {

// One 2 m cell at the origin corner with mean (1, 1, 1) and an isotropic
// covariance of 0.1 m standard deviation (no regularisation applies).
NdtLayer OneCell() {
  NdtCell cell;
  CellRegularization regularization;
  regularization.min_eigenvalue_m2 = 0.0;
  EXPECT_TRUE(MakeNdtCell(20,
                          Eigen::Vector3d(1, 1, 1),
                          0.01 * Eigen::Matrix3d::Identity(),
                          regularization,
                          &cell));
  return NdtLayer(
      Eigen::Vector3d::Zero(), 2.0, Eigen::Vector3i(1, 1, 1), {cell}, {0});
}

TEST(EvaluateFitQuality, CountsOverlapInliersAndDistances) {
  const NdtLayer layer = OneCell();
  // Mahalanobis distances 0, 2 and 5 in the cell, and one point far outside.
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(1, 1, 1),
                                               Eigen::Vector3d(1.2, 1, 1),
                                               Eigen::Vector3d(1, 1.5, 1),
                                               Eigen::Vector3d(9, 9, 9)};
  const FitQuality q =
      EvaluateFitQuality(layer,
                         points,
                         Vector6d::Zero(),
                         testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL),
                         3.0);
  EXPECT_EQ(q.points, 4u);
  EXPECT_DOUBLE_EQ(q.own_cell_fraction, 0.75);
  EXPECT_DOUBLE_EQ(q.inlier_fraction, 0.5);  // Distances 0 and 2 < 3.
  EXPECT_NEAR(q.median_distance, 2.0, 1e-12);
  // Cauchy at the gate, whatever the objective's loss: 9 log(1 + s / 9).
  EXPECT_NEAR(
      q.mean_score,
      9.0 * (std::log1p(0.0) + std::log1p(4.0 / 9.0) + std::log1p(25.0 / 9.0)) /
          3.0,
      1e-12);

  // A tighter gate, and the pose moving every point by 0.2 m along x.
  EXPECT_DOUBLE_EQ(
      EvaluateFitQuality(layer,
                         points,
                         Vector6d::Zero(),
                         testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL),
                         1.0)
          .inlier_fraction,
      0.25);
  Vector6d shift = Vector6d::Zero();
  shift(0) = 0.2;
  const FitQuality moved =
      EvaluateFitQuality(layer,
                         points,
                         shift,
                         testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL),
                         3.0);
  EXPECT_DOUBLE_EQ(moved.inlier_fraction, 0.25);  // Distances 2, 4, 5.39.
  EXPECT_NEAR(moved.median_distance, 4.0, 1e-12);
}

TEST(EvaluateFitQuality, UsesTheObjectivesPolicyNotItsLoss) {
  const NdtLayer layer = OneCell();
  // Just past the cell's +x face: no own cell, the nearest cell is the one.
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(2.05, 1, 1)};
  const FitQuality own =
      EvaluateFitQuality(layer,
                         points,
                         Vector6d::Zero(),
                         testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL),
                         3.0);
  EXPECT_EQ(own.own_cell_fraction, 0.0);
  EXPECT_EQ(own.mean_score, 0.0);  // Nothing matched.
  const FitQuality nearest = EvaluateFitQuality(
      layer,
      points,
      Vector6d::Zero(),
      testing::Objective(UnmatchedPolicy::NEAREST_CELL, LossType::HUBER, 0.5),
      3.0);
  EXPECT_EQ(nearest.own_cell_fraction, 0.0);
  EXPECT_NEAR(nearest.median_distance, 10.5, 1e-9);
  // Cauchy: 9 log(1 + s / 9) with s = 10.5^2.
  EXPECT_NEAR(nearest.mean_score, 9.0 * std::log1p(110.25 / 9.0), 1e-9);
}

TEST(EvaluateFitQuality, NoPointsGiveZeros) {
  const FitQuality q = EvaluateFitQuality(
      OneCell(), {}, Vector6d::Zero(), ObjectiveOptions(), 3.0);
  EXPECT_EQ(q.points, 0u);
  EXPECT_EQ(q.inlier_fraction, 0.0);
  EXPECT_EQ(q.mean_score, 0.0);
}

}  // namespace
}  // namespace mlndt
