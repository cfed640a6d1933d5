#include "mlndt/cost/score.h"

#include <ceres/loss_function.h>
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/objective.h"
#include "tests/testing/tilted_cells.h"

namespace mlndt {
namespace {

using testing::TiltedCovariance;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::EigenNear;

NdtLayer MakeLayer() { return testing::ThreeCellLayer(); }

Vector6d TestPose() {
  Vector6d xi;
  xi << 0.2, -0.1, 0.05, 0.1, -0.05, 0.2;
  return xi;
}

// Input points that TestPose() maps to `targets`.
std::vector<Vector3d> InputPointsFor(const std::vector<Vector3d>& targets) {
  const Vector6d xi = TestPose();
  const Matrix3d r = EulerRotation(xi(3), xi(4), xi(5));
  std::vector<Vector3d> points;
  for (const Vector3d& target : targets)
    points.push_back(r.transpose() * (target - xi.head<3>()));
  return points;
}

// Targets at least 0.1 m from every cell border: 5 in occupied cells (some
// far from the mean, so robust losses are active), 2 in the empty cell
// (2, 1, 0) next to occupied ones.
std::vector<Vector3d> WellInsideTargets() {
  return {Vector3d(2.8, 3.3, 1.1),
          Vector3d(3.7, 2.2, 0.3),
          Vector3d(6.5, 2.4, 3.6),
          Vector3d(7.8, 3.8, 2.2),
          Vector3d(5.0, 4.9, 0.7),
          Vector3d(5.0, 3.8, 1.0),
          Vector3d(4.2, 2.9, 0.8)};
}

// `copies` times WellInsideTargets(), for scores over many points.
std::vector<Vector3d> RepeatedTargets(int copies) {
  std::vector<Vector3d> targets;
  for (int copy = 0; copy < copies; ++copy) {
    for (const Vector3d& target : WellInsideTargets())
      targets.push_back(target);
  }
  return targets;
}

double Score(const NdtLayer& layer,
             const std::vector<Vector3d>& points,
             const Vector6d& xi,
             UnmatchedPolicy policy,
             LossType loss,
             double scale) {
  return EvaluateScore(
             layer, points, xi, testing::Objective(policy, loss, scale))
      .score;
}

struct LossCase {
  LossType loss;
  double scale;
};

TEST(EvaluateScore, GradientEqualsCentralFiniteDifferences) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const Vector6d xi = TestPose();
  constexpr double kStep = 1e-6;
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    for (const LossCase& c : {LossCase{LossType::NONE, 1.0},
                              LossCase{LossType::HUBER, 1.0},
                              LossCase{LossType::CAUCHY, 0.7}}) {
      SCOPED_TRACE(std::string(UnmatchedPolicyToString(policy)) + " " +
                   LossTypeToString(c.loss));
      const ScoreEvaluation evaluation = EvaluateScore(
          layer, points, xi, testing::Objective(policy, c.loss, c.scale));
      Vector6d numeric = Vector6d::Constant(kNaN);
      for (int i = 0; i < 6; ++i) {
        Vector6d plus = xi, minus = xi;
        plus(i) += kStep;
        minus(i) -= kStep;
        numeric(i) = (Score(layer, points, plus, policy, c.loss, c.scale) -
                      Score(layer, points, minus, policy, c.loss, c.scale)) /
                     (2.0 * kStep);
      }
      EXPECT_GT(numeric.norm(), 1.0);
      EXPECT_TRUE(
          EigenNear(evaluation.gradient, numeric, 1e-6 * numeric.norm()));
    }
  }
}

TEST(EvaluateScore, ScoreAndHessianMatchAutoDiffCostFunction) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const Vector6d xi = TestPose();
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    SCOPED_TRACE(UnmatchedPolicyToString(policy));
    double score = 0.0;
    Matrix6d hessian = Matrix6d::Zero();
    Vector6d gradient = Vector6d::Zero();
    for (const Vector3d& p : points) {
      std::unique_ptr<ceres::CostFunction> cost(
          MlNdtPointCost::Create(layer, p, policy));
      Vector3d residual = Vector3d::Constant(kNaN);
      Eigen::Matrix<double, 3, 6, Eigen::RowMajor> jacobian;
      jacobian.setConstant(kNaN);
      const double* parameters[] = {xi.data()};
      double* jacobians[] = {jacobian.data()};
      ASSERT_TRUE(cost->Evaluate(parameters, residual.data(), jacobians));
      score += residual.squaredNorm();
      gradient += 2.0 * jacobian.transpose() * residual;
      hessian += 2.0 * jacobian.transpose() * jacobian;
    }
    const ScoreEvaluation evaluation = EvaluateScore(
        layer, points, xi, testing::Objective(policy, LossType::NONE, 1.0));
    EXPECT_NEAR(evaluation.score, score, 1e-10 * score);
    EXPECT_TRUE(
        EigenNear(evaluation.gradient, gradient, 1e-9 * gradient.norm()));
    EXPECT_TRUE(EigenNear(evaluation.hessian, hessian, 1e-9 * hessian.norm()));
    EXPECT_TRUE(EigenNear(evaluation.hessian,
                          evaluation.hessian.transpose(),
                          1e-14 * hessian.norm()));
    EXPECT_GT(hessian.norm(), 1.0);
  }
}

TEST(EvaluateScore, RobustHessianIsWeightedByLossDerivative) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const Vector6d xi = TestPose();
  const ceres::HuberLoss huber(1.0);
  double score = 0.0;
  Matrix6d hessian = Matrix6d::Zero();
  int down_weighted = 0;
  for (const Vector3d& p : points) {
    std::unique_ptr<ceres::CostFunction> cost(
        MlNdtPointCost::Create(layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
    Vector3d residual;
    Eigen::Matrix<double, 3, 6, Eigen::RowMajor> jacobian;
    const double* parameters[] = {xi.data()};
    double* jacobians[] = {jacobian.data()};
    ASSERT_TRUE(cost->Evaluate(parameters, residual.data(), jacobians));
    if (residual.squaredNorm() == 0.0) continue;  // Unmatched.
    double rho[3];
    huber.Evaluate(residual.squaredNorm(), rho);
    if (rho[1] < 1.0) ++down_weighted;
    score += rho[0];
    hessian += 2.0 * rho[1] * jacobian.transpose() * jacobian;
  }
  ASSERT_GE(down_weighted, 2);  // The loss is active on some points.
  const ScoreEvaluation evaluation = EvaluateScore(
      layer,
      points,
      xi,
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, LossType::HUBER, 1.0));
  EXPECT_NEAR(evaluation.score, score, 1e-10 * score);
  EXPECT_TRUE(EigenNear(evaluation.hessian, hessian, 1e-9 * hessian.norm()));
}

// The Cauchy score is summed as b log(prod (1 + s_k / b)), renormalised as
// it grows (score.cc): it must equal the sum of each point's loss, here over
// 1400 points whose product passes 2^500 several times.
TEST(EvaluateScore, CauchyScoreIsTheSumOfEachPointsLoss) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(RepeatedTargets(200));
  const Vector6d xi = TestPose();
  const ceres::CauchyLoss cauchy(1.5);
  double score = 0.0;
  int matched = 0;
  for (const Vector3d& p : points) {
    std::unique_ptr<ceres::CostFunction> cost(
        MlNdtPointCost::Create(layer, p, UnmatchedPolicy::NEAREST_CELL));
    Vector3d residual;
    const double* parameters[] = {xi.data()};
    ASSERT_TRUE(cost->Evaluate(parameters, residual.data(), nullptr));
    if (residual.squaredNorm() == 0.0) continue;
    double rho[3];
    cauchy.Evaluate(residual.squaredNorm(), rho);
    score += rho[0];
    ++matched;
  }
  // sum log2(1 + s / b) = score / (b ln 2): the product passed 2^500.
  ASSERT_GT(score / (1.5 * 1.5 * M_LN2), 1500.0);
  const ScoreEvaluation evaluation = EvaluateScore(
      layer,
      points,
      xi,
      testing::Objective(UnmatchedPolicy::NEAREST_CELL, LossType::CAUCHY, 1.5));
  EXPECT_EQ(evaluation.matched, static_cast<size_t>(matched));
  EXPECT_NEAR(evaluation.score, score, 1e-12 * score);
}

TEST(EvaluateScore, FullHessianEqualsFiniteDifferencesOfGradient) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const Vector6d xi = TestPose();
  constexpr double kStep = 1e-6;
  for (const LossType loss : {LossType::NONE, LossType::HUBER}) {
    SCOPED_TRACE(LossTypeToString(loss));
    const ObjectiveOptions options =
        testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, loss);
    const ScoreEvaluation full =
        EvaluateScore(layer, points, xi, options, HessianType::FULL);
    Matrix6d numeric = Matrix6d::Constant(kNaN);
    for (int i = 0; i < 6; ++i) {
      Vector6d plus = xi, minus = xi;
      plus(i) += kStep;
      minus(i) -= kStep;
      numeric.col(i) = (EvaluateScore(layer, points, plus, options).gradient -
                        EvaluateScore(layer, points, minus, options).gradient) /
                       (2.0 * kStep);
    }
    if (loss == LossType::NONE) {
      // Exact Newton Hessian (Eq. 14) without a robust loss.
      EXPECT_TRUE(EigenNear(full.hessian, numeric, 1e-6 * numeric.norm()));
    }
    // The second-order term is what FULL adds to GAUSS_NEWTON.
    const ScoreEvaluation gauss_newton =
        EvaluateScore(layer, points, xi, options, HessianType::GAUSS_NEWTON);
    EXPECT_GT((full.hessian - gauss_newton.hessian).norm(),
              1e-3 * full.hessian.norm());
    EXPECT_TRUE(EigenNear(full.hessian.topLeftCorner<3, 3>(),
                          gauss_newton.hessian.topLeftCorner<3, 3>(),
                          1e-12 * full.hessian.norm()));
    EXPECT_TRUE(EigenNear(full.gradient, gauss_newton.gradient, 0.0));
    EXPECT_EQ(full.score, gauss_newton.score);
  }
}

TEST(EvaluateScore, HessianNoneSkipsDerivatives) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const ObjectiveOptions options =
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL);
  const ScoreEvaluation none =
      EvaluateScore(layer, points, TestPose(), options, HessianType::NONE);
  const ScoreEvaluation gauss_newton = EvaluateScore(
      layer,
      points,
      TestPose(),
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0));
  EXPECT_EQ(none.score, gauss_newton.score);
  EXPECT_EQ(none.matched, gauss_newton.matched);
  EXPECT_EQ(none.unmatched, gauss_newton.unmatched);
  EXPECT_GT(none.score, 0.0);
}

TEST(EvaluateScore, ThreadCountDoesNotChangeTheResult) {
  const NdtLayer layer = MakeLayer();
  std::vector<Vector3d> targets = RepeatedTargets(20);
  targets.push_back(Vector3d(-50.0, 3.0, 1.0));
  const std::vector<Vector3d> points = InputPointsFor(targets);
  const ObjectiveOptions options =
      testing::Objective(UnmatchedPolicy::NEAREST_CELL);
  const ScoreEvaluation one =
      EvaluateScore(layer, points, TestPose(), options, HessianType::FULL, 1);
  const ScoreEvaluation three =
      EvaluateScore(layer, points, TestPose(), options, HessianType::FULL, 3);
  const ScoreEvaluation again =
      EvaluateScore(layer, points, TestPose(), options, HessianType::FULL, 3);
  EXPECT_EQ(three.matched, one.matched);
  EXPECT_EQ(three.unmatched, one.unmatched);
  EXPECT_EQ(three.matched + three.unmatched, points.size());
  EXPECT_NEAR(three.score, one.score, 1e-12 * one.score);
  EXPECT_TRUE(
      EigenNear(three.gradient, one.gradient, 1e-12 * one.gradient.norm()));
  EXPECT_TRUE(
      EigenNear(three.hessian, one.hessian, 1e-12 * one.hessian.norm()));
  // The same thread count gives the same bits.
  EXPECT_EQ(again.score, three.score);
  EXPECT_TRUE(EigenNear(again.hessian, three.hessian, 0.0));
  // More threads than points.
  const std::vector<Vector3d> two(points.begin(), points.begin() + 2);
  const ScoreEvaluation few =
      EvaluateScore(layer, two, TestPose(), options, HessianType::FULL, 8);
  EXPECT_EQ(few.matched + few.unmatched, 2u);
}

TEST(EvaluateScore, CountsMatchedAndUnmatchedPoints) {
  const NdtLayer layer = MakeLayer();
  // 5 in occupied cells, 2 in an empty cell next to occupied ones, 2 outside
  // the grid with no occupied neighbour.
  std::vector<Vector3d> targets = WellInsideTargets();
  targets.push_back(Vector3d(-50.0, 3.0, 1.0));
  targets.push_back(Vector3d(0.5, 30.0, 3.0));
  const std::vector<Vector3d> points = InputPointsFor(targets);
  const Vector6d xi = TestPose();

  const ScoreEvaluation zero = EvaluateScore(
      layer,
      points,
      xi,
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0));
  EXPECT_EQ(zero.matched, 5u);
  EXPECT_EQ(zero.unmatched, 4u);
  EXPECT_EQ(zero.matched + zero.unmatched, points.size());

  const ScoreEvaluation nearest = EvaluateScore(
      layer,
      points,
      xi,
      testing::Objective(UnmatchedPolicy::NEAREST_CELL, LossType::NONE, 1.0));
  EXPECT_EQ(nearest.matched, 7u);
  EXPECT_EQ(nearest.unmatched, 2u);
  EXPECT_EQ(nearest.matched + nearest.unmatched, points.size());
  EXPECT_GT(nearest.score, zero.score);

  // Unmatched points contribute nothing: the score over the 5 matched points
  // alone is the same.
  const std::vector<Vector3d> matched_only(points.begin(), points.begin() + 5);
  const ScoreEvaluation five = EvaluateScore(
      layer,
      matched_only,
      xi,
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0));
  EXPECT_NEAR(five.score, zero.score, 1e-12 * zero.score);
  EXPECT_TRUE(
      EigenNear(five.gradient, zero.gradient, 1e-12 * zero.gradient.norm()));

  const ScoreEvaluation empty = EvaluateScore(
      layer,
      {},
      xi,
      testing::Objective(UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0));
  EXPECT_EQ(empty.matched + empty.unmatched, 0u);
  EXPECT_EQ(empty.score, 0.0);
  EXPECT_TRUE(EigenNear(empty.hessian, Matrix6d::Zero(), 0.0));
}

TEST(RobustLoss, EvaluateLossEqualsCeresLosses) {
  for (const double scale : {0.3, 1.0, 2.5}) {
    const ceres::HuberLoss huber(scale);
    const ceres::CauchyLoss cauchy(scale);
    for (const double s : {0.0, 0.01, 0.09, 0.5, 1.0, 3.0, 6.25, 40.0, 1e4}) {
      SCOPED_TRACE("scale " + std::to_string(scale) + " s " +
                   std::to_string(s));
      double expected[3];
      double rho = kNaN, rho_prime = kNaN;

      huber.Evaluate(s, expected);
      EvaluateLoss(LossType::HUBER, scale, s, &rho, &rho_prime);
      EXPECT_NEAR(rho, expected[0], 1e-12 * (1.0 + expected[0]));
      EXPECT_NEAR(rho_prime, expected[1], 1e-12);

      rho = rho_prime = kNaN;
      cauchy.Evaluate(s, expected);
      EvaluateLoss(LossType::CAUCHY, scale, s, &rho, &rho_prime);
      EXPECT_NEAR(rho, expected[0], 1e-12 * (1.0 + expected[0]));
      EXPECT_NEAR(rho_prime, expected[1], 1e-12);

      rho = rho_prime = kNaN;
      EvaluateLoss(LossType::NONE, scale, s, &rho, &rho_prime);
      EXPECT_EQ(rho, s);
      EXPECT_EQ(rho_prime, 1.0);
    }
  }
}

TEST(RobustLoss, CreateLossReturnsTheMatchingCeresLoss) {
  EXPECT_EQ(CreateLoss(LossType::NONE, 1.0), nullptr);
  std::unique_ptr<ceres::LossFunction> huber(CreateLoss(LossType::HUBER, 2.0));
  std::unique_ptr<ceres::LossFunction> cauchy(
      CreateLoss(LossType::CAUCHY, 2.0));
  EXPECT_NE(dynamic_cast<ceres::HuberLoss*>(huber.get()), nullptr);
  EXPECT_NE(dynamic_cast<ceres::CauchyLoss*>(cauchy.get()), nullptr);
  // The scale is passed through: Huber is quadratic up to s = scale^2 = 4.
  double rho[3];
  huber->Evaluate(3.9, rho);
  EXPECT_DOUBLE_EQ(rho[0], 3.9);
  huber->Evaluate(9.0, rho);
  EXPECT_DOUBLE_EQ(rho[0], 2.0 * 2.0 * 3.0 - 4.0);
}

TEST(RobustLoss, LossTypeStringRoundTrip) {
  for (const LossType type :
       {LossType::NONE, LossType::HUBER, LossType::CAUCHY}) {
    LossType parsed =
        type == LossType::NONE ? LossType::CAUCHY : LossType::NONE;
    ASSERT_TRUE(StringToLossType(LossTypeToString(type), &parsed))
        << LossTypeToString(type);
    EXPECT_EQ(parsed, type);
  }
  LossType parsed = LossType::NONE;
  EXPECT_TRUE(StringToLossType("huber", &parsed));
  EXPECT_EQ(parsed, LossType::HUBER);
  EXPECT_FALSE(StringToLossType("TUKEY", &parsed));
  EXPECT_FALSE(StringToLossType("", &parsed));
  EXPECT_EQ(parsed, LossType::HUBER);  // Untouched on failure.
}

TEST(CellMatch, UnmatchedPolicyStringRoundTrip) {
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    UnmatchedPolicy parsed = policy == UnmatchedPolicy::ZERO_RESIDUAL
                                 ? UnmatchedPolicy::NEAREST_CELL
                                 : UnmatchedPolicy::ZERO_RESIDUAL;
    ASSERT_TRUE(
        StringToUnmatchedPolicy(UnmatchedPolicyToString(policy), &parsed))
        << UnmatchedPolicyToString(policy);
    EXPECT_EQ(parsed, policy);
  }
  EXPECT_STREQ(UnmatchedPolicyToString(UnmatchedPolicy::NEAREST_CELL),
               "NEAREST_CELL");
  UnmatchedPolicy parsed = UnmatchedPolicy::ZERO_RESIDUAL;
  EXPECT_TRUE(StringToUnmatchedPolicy("nearest_cell", &parsed));
  EXPECT_EQ(parsed, UnmatchedPolicy::NEAREST_CELL);
  EXPECT_FALSE(StringToUnmatchedPolicy("NEAREST", &parsed));
  EXPECT_EQ(parsed, UnmatchedPolicy::NEAREST_CELL);
}

}  // namespace
}  // namespace mlndt
