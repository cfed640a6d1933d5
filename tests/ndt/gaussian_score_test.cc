#include "mlndt/ndt/gaussian_score.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "tests/testing/tilted_cells.h"

namespace mlndt {
namespace {

using testing::TiltedCovariance;

// Cells of 2 m over a 4 x 3 x 2 grid at the origin.
constexpr double kCellSize = 2.0;

int64_t Key(int i, int j, int k) { return i + 4 * (j + 3 * k); }

// Occupied cells with non-diagonal covariances: (1, 1, 0); its face
// neighbour (2, 1, 0); (2, 2, 1), which only touches (1, 1, 0) along an
// edge; and (3, 1, 1). All others are empty.
NdtLayer MakeLayer() {
  std::vector<NdtCell> cells(4);
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(3.1, 2.9, 0.8),
                  TiltedCovariance({0.40, 0.15, 0.05}, 0.7, {1.0, 2.0, -0.5}),
                  CellRegularization(),
                  &cells[0]));
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(4.9, 3.2, 1.1),
                  TiltedCovariance({0.30, 0.20, 0.06}, 1.1, {-0.3, 1.0, 1.0}),
                  CellRegularization(),
                  &cells[1]));
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(5.2, 4.6, 2.9),
                  TiltedCovariance({0.50, 0.10, 0.04}, 0.4, {0.2, -1.0, 0.6}),
                  CellRegularization(),
                  &cells[2]));
  EXPECT_TRUE(
      MakeNdtCell(20,
                  Vector3d(7.0, 3.1, 3.0),
                  TiltedCovariance({0.35, 0.25, 0.05}, 0.9, {1.0, 0.0, 1.0}),
                  CellRegularization(),
                  &cells[3]));
  return NdtLayer(Vector3d::Zero(),
                  kCellSize,
                  Eigen::Vector3i(4, 3, 2),
                  cells,
                  {Key(1, 1, 0), Key(2, 1, 0), Key(2, 2, 1), Key(3, 1, 1)});
}

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

// Targets at least 0.1 m from every cell border, so that finite differences
// never move a point into another cell: in each occupied cell (some far
// from the mean), and in empty cells next to occupied ones.
std::vector<Vector3d> WellInsideTargets() {
  return {Vector3d(2.8, 3.3, 1.1),
          Vector3d(3.7, 2.2, 0.3),
          Vector3d(4.6, 3.5, 1.4),
          Vector3d(5.5, 2.4, 0.6),
          Vector3d(5.0, 4.9, 2.7),
          Vector3d(6.5, 3.6, 3.2),
          Vector3d(7.8, 2.4, 2.2),
          Vector3d(1.0, 3.0, 1.0),
          Vector3d(3.0, 2.9, 2.9)};
}

GaussianScoreOptions Options(NdtNeighbors neighbors, HessianType hessian) {
  GaussianScoreOptions options;
  options.neighbors = neighbors;
  options.hessian = hessian;
  return options;
}

// Central differences of the score (gradient) or the analytic gradient
// (Hessian) in xi.
Vector6d NumericGradient(const NdtLayer& layer,
                         const std::vector<Vector3d>& points,
                         const Vector6d& xi,
                         NdtNeighbors neighbors) {
  const double h = 1e-6;
  Vector6d g;
  for (int i = 0; i < 6; ++i) {
    Vector6d plus = xi, minus = xi;
    plus(i) += h;
    minus(i) -= h;
    const GaussianScoreOptions options = Options(neighbors, HessianType::NONE);
    g(i) = (EvaluateGaussianScore(layer, points, plus, options).score -
            EvaluateGaussianScore(layer, points, minus, options).score) /
           (2.0 * h);
  }
  return g;
}

Matrix6d NumericHessian(const NdtLayer& layer,
                        const std::vector<Vector3d>& points,
                        const Vector6d& xi,
                        NdtNeighbors neighbors) {
  const double h = 1e-6;
  Matrix6d hessian;
  for (int i = 0; i < 6; ++i) {
    Vector6d plus = xi, minus = xi;
    plus(i) += h;
    minus(i) -= h;
    const GaussianScoreOptions options =
        Options(neighbors, HessianType::GAUSS_NEWTON);
    hessian.col(i) =
        (EvaluateGaussianScore(layer, points, plus, options).gradient -
         EvaluateGaussianScore(layer, points, minus, options).gradient) /
        (2.0 * h);
  }
  return hessian;
}

TEST(GaussianScoreParameters, PclDefaultsByHand) {
  // PCL's defaults: outlier ratio 0.55, resolution 1 m. c1 = 4.5, c2 = 0.55,
  // d3 = -log(0.55) = 0.597837, d1 = log(0.55 / 5.05) = -2.217225,
  // d2 = -2 log(log(0.55 / (4.5 e^-0.5 + 0.55)) / d1)
  //    = -2 log(-1.785493 / -2.217225) = 0.433123.
  const GaussianScoreParameters p = ComputeGaussianScoreParameters(0.55, 1.0);
  EXPECT_NEAR(p.d1, -2.217225, 1e-6);
  EXPECT_NEAR(p.d2, 0.433123, 1e-6);
  EXPECT_NEAR(p.d3, 0.597837, 1e-6);
  const double c1 = 4.5, c2 = 0.55;
  EXPECT_NEAR(p.d1, std::log(c2 / (c1 + c2)), 1e-12);
  EXPECT_NEAR(p.d2,
              -2.0 * std::log(std::log(c2 / (c1 * std::exp(-0.5) + c2)) /
                              std::log(c2 / (c1 + c2))),
              1e-12);
}

TEST(GaussianScoreParameters, SignsForAnyRatioAndCellSize) {
  for (double ratio : {0.01, 0.3, 0.55, 0.9}) {
    for (double cell : {0.5, 1.0, 2.0, 15.0}) {
      const GaussianScoreParameters p =
          ComputeGaussianScoreParameters(ratio, cell);
      EXPECT_LT(p.d1, 0.0) << ratio << " " << cell;
      EXPECT_GT(p.d2, 0.0) << ratio << " " << cell;
      EXPECT_TRUE(std::isfinite(p.d1) && std::isfinite(p.d2));
    }
  }
}

TEST(GaussianScore, SinglePointValueByHand) {
  const NdtLayer layer = MakeLayer();
  const Vector3d target(2.8, 3.3, 1.1);  // In cell (1, 1, 0) only.
  const std::vector<Vector3d> points = InputPointsFor({target});
  const NdtCell& cell = layer.cells()[0];
  const Vector3d e = target - cell.mean;
  const double q = e.dot(cell.information * e);
  const GaussianScoreParameters p =
      ComputeGaussianScoreParameters(0.55, kCellSize);
  const ScoreEvaluation evaluation =
      EvaluateGaussianScore(layer,
                            points,
                            TestPose(),
                            Options(NdtNeighbors::DIRECT1, HessianType::FULL));
  // Lower is better: d1 exp(-d2 q / 2), the negated PCL per-point score.
  EXPECT_NEAR(evaluation.score, p.d1 * std::exp(-0.5 * p.d2 * q), 1e-12);
  EXPECT_LT(evaluation.score, 0.0);
  EXPECT_EQ(evaluation.matched, 1u);
  EXPECT_EQ(evaluation.unmatched, 0u);
}

TEST(GaussianScore, PointAtTheMeanHasTheLowestScore) {
  const NdtLayer layer = MakeLayer();
  const GaussianScoreParameters p =
      ComputeGaussianScoreParameters(0.55, kCellSize);
  const ScoreEvaluation at_mean =
      EvaluateGaussianScore(layer,
                            InputPointsFor({layer.cells()[0].mean}),
                            TestPose(),
                            Options(NdtNeighbors::DIRECT1, HessianType::FULL));
  EXPECT_NEAR(at_mean.score, p.d1, 1e-12);
  EXPECT_LT(at_mean.gradient.norm(), 1e-9);
}

TEST(GaussianScore, UnmatchedPointsContributeNothing) {
  const NdtLayer layer = MakeLayer();
  // Points in empty cells without occupied face neighbours, and outside.
  const std::vector<Vector3d> targets = {
      Vector3d(1.0, 1.0, 1.0),       // (0, 0, 0), empty.
      Vector3d(0.9, 5.0, 3.0),       // (0, 2, 1), empty.
      Vector3d(100.0, -50.0, 3.0)};  // Outside.
  for (NdtNeighbors neighbors :
       {NdtNeighbors::DIRECT1, NdtNeighbors::DIRECT7}) {
    const ScoreEvaluation evaluation =
        EvaluateGaussianScore(layer,
                              InputPointsFor(targets),
                              TestPose(),
                              Options(neighbors, HessianType::FULL));
    EXPECT_EQ(evaluation.score, 0.0);
    EXPECT_EQ(evaluation.matched, 0u);
    EXPECT_EQ(evaluation.unmatched, 3u);
    EXPECT_EQ(evaluation.gradient, Vector6d::Zero());
    EXPECT_EQ(evaluation.hessian, Matrix6d::Zero());
  }
}

TEST(GaussianScore, Direct7AddsFaceNeighboursOnly) {
  const NdtLayer layer = MakeLayer();
  const GaussianScoreParameters p =
      ComputeGaussianScoreParameters(0.55, kCellSize);
  const Vector3d target(3.7, 2.2, 0.3);  // Cell (1, 1, 0).
  const auto term = [&](const NdtCell& cell) {
    const Vector3d e = target - cell.mean;
    return p.d1 * std::exp(-0.5 * p.d2 * e.dot(cell.information * e));
  };
  const std::vector<Vector3d> points = InputPointsFor({target});
  const double direct1 =
      EvaluateGaussianScore(layer,
                            points,
                            TestPose(),
                            Options(NdtNeighbors::DIRECT1, HessianType::NONE))
          .score;
  const double direct7 =
      EvaluateGaussianScore(layer,
                            points,
                            TestPose(),
                            Options(NdtNeighbors::DIRECT7, HessianType::NONE))
          .score;
  EXPECT_NEAR(direct1, term(layer.cells()[0]), 1e-12);
  // (2, 1, 0) is a face neighbour; (2, 2, 1) shares only an edge.
  EXPECT_NEAR(direct7, term(layer.cells()[0]) + term(layer.cells()[1]), 1e-12);

  // A point in an empty cell next to an occupied one is matched by DIRECT7.
  const std::vector<Vector3d> beside =
      InputPointsFor({Vector3d(3.0, 0.9, 0.9)});  // (1, 0, 0).
  EXPECT_EQ(
      EvaluateGaussianScore(layer,
                            beside,
                            TestPose(),
                            Options(NdtNeighbors::DIRECT1, HessianType::NONE))
          .matched,
      0u);
  EXPECT_EQ(
      EvaluateGaussianScore(layer,
                            beside,
                            TestPose(),
                            Options(NdtNeighbors::DIRECT7, HessianType::NONE))
          .matched,
      1u);
}

class GaussianScoreDerivatives : public ::testing::TestWithParam<NdtNeighbors> {
};

TEST_P(GaussianScoreDerivatives, GradientMatchesFiniteDifferences) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const ScoreEvaluation evaluation = EvaluateGaussianScore(
      layer, points, TestPose(), Options(GetParam(), HessianType::FULL));
  ASSERT_GT(evaluation.matched, 5u);
  const Vector6d numeric =
      NumericGradient(layer, points, TestPose(), GetParam());
  EXPECT_LT((evaluation.gradient - numeric).cwiseAbs().maxCoeff(),
            1e-6 * std::max(1.0, numeric.cwiseAbs().maxCoeff()))
      << "analytic " << evaluation.gradient.transpose() << "\nnumeric  "
      << numeric.transpose();
}

TEST_P(GaussianScoreDerivatives, FullHessianMatchesFiniteDifferences) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const ScoreEvaluation evaluation = EvaluateGaussianScore(
      layer, points, TestPose(), Options(GetParam(), HessianType::FULL));
  const Matrix6d numeric =
      NumericHessian(layer, points, TestPose(), GetParam());
  EXPECT_LT((evaluation.hessian - numeric).cwiseAbs().maxCoeff(),
            1e-5 * std::max(1.0, numeric.cwiseAbs().maxCoeff()))
      << "analytic\n"
      << evaluation.hessian << "\nnumeric\n"
      << numeric;
  EXPECT_LT((evaluation.hessian - evaluation.hessian.transpose())
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
}

TEST_P(GaussianScoreDerivatives, GaussNewtonHessianIsPositiveSemiDefinite) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const ScoreEvaluation gauss_newton =
      EvaluateGaussianScore(layer,
                            points,
                            TestPose(),
                            Options(GetParam(), HessianType::GAUSS_NEWTON));
  const ScoreEvaluation full = EvaluateGaussianScore(
      layer, points, TestPose(), Options(GetParam(), HessianType::FULL));
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(gauss_newton.hessian);
  EXPECT_GE(solver.eigenvalues().minCoeff(), -1e-12);
  EXPECT_EQ(gauss_newton.score, full.score);
  EXPECT_EQ(gauss_newton.gradient, full.gradient);
  EXPECT_GT((gauss_newton.hessian - full.hessian).norm(),
            0.0);  // The dropped terms.
}

TEST_P(GaussianScoreDerivatives, NoneGivesTheScoreOnly) {
  const NdtLayer layer = MakeLayer();
  const std::vector<Vector3d> points = InputPointsFor(WellInsideTargets());
  const ScoreEvaluation none = EvaluateGaussianScore(
      layer, points, TestPose(), Options(GetParam(), HessianType::NONE));
  const ScoreEvaluation full = EvaluateGaussianScore(
      layer, points, TestPose(), Options(GetParam(), HessianType::FULL));
  EXPECT_EQ(none.score, full.score);
  EXPECT_EQ(none.matched, full.matched);
  EXPECT_EQ(none.unmatched, full.unmatched);
  EXPECT_EQ(none.gradient, Vector6d::Zero());
  EXPECT_EQ(none.hessian, Matrix6d::Zero());
}

TEST_P(GaussianScoreDerivatives, ThreadsGiveTheSameSums) {
  const NdtLayer layer = MakeLayer();
  std::vector<Vector3d> points;
  for (int r = 0; r < 20; ++r) {
    for (const Vector3d& p : InputPointsFor(WellInsideTargets()))
      points.push_back(p);
  }
  GaussianScoreOptions options = Options(GetParam(), HessianType::FULL);
  const ScoreEvaluation one =
      EvaluateGaussianScore(layer, points, TestPose(), options);
  options.num_threads = 3;
  const ScoreEvaluation three =
      EvaluateGaussianScore(layer, points, TestPose(), options);
  EXPECT_NEAR(one.score, three.score, 1e-9 * std::abs(one.score));
  EXPECT_EQ(one.matched, three.matched);
  EXPECT_LT((one.gradient - three.gradient).norm(),
            1e-9 * (1.0 + one.gradient.norm()));
  EXPECT_LT((one.hessian - three.hessian).norm(),
            1e-9 * (1.0 + one.hessian.norm()));
}

INSTANTIATE_TEST_SUITE_P(
    Neighbors,
    GaussianScoreDerivatives,
    ::testing::Values(NdtNeighbors::DIRECT1, NdtNeighbors::DIRECT7),
    [](const ::testing::TestParamInfo<NdtNeighbors>& info) {
      return std::string(NdtNeighborsToString(info.param));
    });

TEST(GaussianScoreOptions, Validation) {
  std::string error;
  EXPECT_TRUE(GaussianScoreOptions().IsValid(&error)) << error;
  GaussianScoreOptions options;
  options.outlier_ratio = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("outlier_ratio"), std::string::npos) << error;
  options.outlier_ratio = 1.0;
  EXPECT_FALSE(options.IsValid(&error));
  options = GaussianScoreOptions();
  options.num_threads = 0;
  EXPECT_FALSE(options.IsValid(&error));
}

TEST(NdtNeighbors, StringsRoundTrip) {
  for (NdtNeighbors n : {NdtNeighbors::DIRECT1, NdtNeighbors::DIRECT7}) {
    NdtNeighbors parsed = n == NdtNeighbors::DIRECT1 ? NdtNeighbors::DIRECT7
                                                     : NdtNeighbors::DIRECT1;
    EXPECT_TRUE(StringToNdtNeighbors(NdtNeighborsToString(n), &parsed));
    EXPECT_EQ(parsed, n);
  }
  NdtNeighbors parsed;
  EXPECT_TRUE(StringToNdtNeighbors("direct7", &parsed));
  EXPECT_EQ(parsed, NdtNeighbors::DIRECT7);
  EXPECT_FALSE(StringToNdtNeighbors("direct27", &parsed));
}

}  // namespace
}  // namespace mlndt
