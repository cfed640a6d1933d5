#include "mlndt/cost/scalar_residual.h"

#include <gtest/gtest.h>

#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"
#include "mlndt/solvers/objective.h"
#include "tests/testing/tilted_cells.h"

namespace mlndt {
namespace {

using testing::TiltedCovariance;

NdtLayer MakeLayer() { return testing::ThreeCellLayer(); }

// Points spread around the three cell means, pulled back by `xi` so that xi
// maps them near the means.
std::vector<Vector3d> Points(const Vector6d& xi) {
  const Matrix3d r = EulerRotation(xi(3), xi(4), xi(5));
  std::vector<Vector3d> points;
  for (const Vector3d& mean : {Vector3d(3.1, 2.9, 0.8),
                               Vector3d(7.0, 3.2, 2.9),
                               Vector3d(5.2, 4.6, 1.1)}) {
    for (int i = 0; i < 8; ++i) {
      const Vector3d d(0.3 * ((i & 1) ? 1 : -1),
                       0.25 * ((i & 2) ? 1 : -1),
                       0.1 * ((i & 4) ? 1 : -1));
      points.push_back(r.transpose() * (mean + d - xi.head<3>()));
    }
  }
  return points;
}

Vector6d Pose() {
  Vector6d xi;
  xi << 0.2, -0.1, 0.05, 0.1, -0.05, 0.2;
  return xi;
}

ObjectiveOptions PaperObjective() { return PaperObjectiveOptions(); }

// s_k of each point at xi, from EvaluateScore one point at a time.
std::vector<double> Scores(const NdtLayer& layer,
                           const std::vector<Vector3d>& points,
                           const Vector6d& xi) {
  std::vector<double> s;
  for (const Vector3d& p : points) {
    s.push_back(
        EvaluateScore(layer, {p}, xi, PaperObjective(), HessianType::NONE)
            .score);
  }
  return s;
}

// Catches: a factor 2 missing in J_k, the angle block of J_k, J^T r
// accumulated with s_k^2 or without r_k, J^T J not the outer products.
TEST(EvaluateScalarResidualSystem, MatchesFiniteDifferencesOfTheResiduals) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = Points(Pose());
  Vector6d xi = Pose();
  xi(0) += 0.05;
  xi(5) -= 0.02;
  const ScalarResidualSystem system =
      EvaluateScalarResidualSystem(layer, points, xi, PaperObjective());
  const ScoreEvaluation score =
      EvaluateScore(layer, points, xi, PaperObjective(), HessianType::NONE);
  EXPECT_NEAR(system.score, score.score, 1e-9 * score.score);
  EXPECT_EQ(system.matched, score.matched);
  // Per point J_k by central differences; then J^T J and J^T r.
  const std::vector<double> s0 = Scores(layer, points, xi);
  std::vector<Vector6d> j(points.size(), Vector6d::Zero());
  const double h = 1e-6;
  for (int a = 0; a < 6; ++a) {
    Vector6d plus = xi, minus = xi;
    plus(a) += h;
    minus(a) -= h;
    const std::vector<double> sp = Scores(layer, points, plus);
    const std::vector<double> sm = Scores(layer, points, minus);
    for (size_t k = 0; k < points.size(); ++k)
      j[k](a) = (sp[k] - sm[k]) / (2 * h);
  }
  Matrix6d jtj = Matrix6d::Zero();
  Vector6d jtr = Vector6d::Zero();
  for (size_t k = 0; k < points.size(); ++k) {
    jtj += j[k] * j[k].transpose();
    jtr += s0[k] * j[k];
  }
  EXPECT_LT((system.jtr - jtr).norm(), 1e-5 * jtr.norm());
  EXPECT_LT((system.jtj - jtj).norm(), 1e-5 * jtj.norm());
}

// Catches: the option ignored (the whitened system runs instead: the first
// step would be the same), a step of the wrong sign (the score would not
// fall to the minimum).
TEST(MinimizeLevenbergMarquardt, ScalarScoreResidualLowersTheScore) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = Points(Pose());
  // Nearest-cell scoring: with own cells only a point can lower the score
  // by leaving its cell, whichever minimiser runs.
  const MlNdtObjective objective(layer, points, ObjectiveOptions(), 1);
  Vector6d xi = Pose();
  xi(0) += 0.05;
  xi(1) -= 0.04;
  xi(5) += 0.02;
  const double start = objective.Evaluate(xi, HessianType::NONE).score;
  LevenbergMarquardtOptions options;
  options.residual = LmResidual::SCALAR_SCORE;
  StageControl control;
  control.max_iterations = 50;
  control.step_tolerance = 1e-8;
  StageSummary scalar;
  Vector6d xi_scalar = xi;
  MinimizeLevenbergMarquardt(objective, options, control, &xi_scalar, &scalar);
  EXPECT_NE(scalar.termination_type, TerminationType::FAILURE)
      << scalar.message;
  // Not the whitened minimiser's path.
  StageSummary whitened;
  Vector6d xi_whitened = xi;
  MinimizeLevenbergMarquardt(
      objective, LevenbergMarquardtOptions(), control, &xi_whitened, &whitened);
  // Both end at the score's minimum (not Pose(): the points' spread turns
  // against the tilted covariances; the valley is flat, so only the scores
  // are compared), the scalar residuals more slowly.
  EXPECT_LT(scalar.final_score, start);
  EXPECT_NEAR(
      scalar.final_score, whitened.final_score, 0.01 * whitened.final_score);
  ASSERT_FALSE(scalar.trace.empty());
  ASSERT_FALSE(whitened.trace.empty());
  EXPECT_GT((scalar.trace[0].reference_from_input_xi -
             whitened.trace[0].reference_from_input_xi)
                .norm(),
            1e-6);
}

TEST(LmResidual, StringsRoundTripAndOptionIsChecked) {
  for (const LmResidual r : {LmResidual::WHITENED, LmResidual::SCALAR_SCORE}) {
    LmResidual parsed;
    ASSERT_TRUE(StringToLmResidual(LmResidualToString(r), &parsed));
    EXPECT_EQ(parsed, r);
  }
  LmResidual parsed;
  EXPECT_TRUE(StringToLmResidual("scalar_score", &parsed));
  EXPECT_FALSE(StringToLmResidual("scalar", &parsed));
  LevenbergMarquardtOptions options;
  options.residual = static_cast<LmResidual>(7);
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("residual"), std::string::npos);
}

}  // namespace
}  // namespace mlndt
