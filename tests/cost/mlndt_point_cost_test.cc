#include "mlndt/cost/mlndt_point_cost.h"

#include <ceres/gradient_checker.h>
#include <ceres/jet.h>
#include <ceres/manifold.h>
#include <ceres/numeric_diff_options.h>
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/tilted_cells.h"

namespace mlndt {
namespace {

using testing::TiltedCovariance;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::EigenNear;

Matrix3d ElementaryProduct(double alpha, double beta, double gamma) {
  return (Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(gamma, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// Q diag(l) Q^T with a tilted Q: a non-diagonal covariance with known
// eigenvalues, all above the regularisation floors (so MakeNdtCell keeps it).
// A hand-built layer: origin 0, 2 m cells, 4 x 3 x 2 grid, three occupied
// cells with non-diagonal covariances:
//   A at (1, 1, 0): x in [2, 4), y in [2, 4), z in [0, 2)
//   C at (2, 2, 0): x in [4, 6), y in [4, 6), z in [0, 2)
//   B at (3, 1, 1): x in [6, 8), y in [2, 4), z in [2, 4)
// Cell (2, 1, 0) is empty and has all three as neighbours.
struct HandLayer {
  Vector3d mean_a{3.1, 2.9, 0.8};
  Vector3d mean_b{7.0, 3.2, 2.9};
  Vector3d mean_c{5.2, 4.6, 1.1};
  Matrix3d cov_a = TiltedCovariance({0.40, 0.15, 0.05}, 0.7, {1.0, 2.0, -0.5});
  Matrix3d cov_b = TiltedCovariance({0.30, 0.20, 0.02}, 1.1, {-0.3, 1.0, 1.0});
  Matrix3d cov_c = TiltedCovariance({0.50, 0.10, 0.03}, 0.4, {0.2, -1.0, 0.6});
  NdtLayer layer;

  HandLayer() {
    const Eigen::Vector3i dims(4, 3, 2);
    const auto key = [&](int i, int j, int k) -> int64_t {
      return i + 4 * (j + 3 * k);
    };
    std::vector<NdtCell> cells(3);
    EXPECT_TRUE(
        MakeNdtCell(20, mean_a, cov_a, CellRegularization(), &cells[0]));
    EXPECT_TRUE(
        MakeNdtCell(20, mean_b, cov_b, CellRegularization(), &cells[1]));
    EXPECT_TRUE(
        MakeNdtCell(20, mean_c, cov_c, CellRegularization(), &cells[2]));
    layer = NdtLayer(Vector3d::Zero(),
                     2.0,
                     dims,
                     cells,
                     {key(1, 1, 0), key(3, 1, 1), key(2, 2, 0)});
  }

  const NdtCell& a() const { return *layer.CellAt({1, 1, 0}); }
  const NdtCell& b() const { return *layer.CellAt({3, 1, 1}); }
  const NdtCell& c() const { return *layer.CellAt({2, 2, 0}); }
};

// GradientChecker differentiates with Ridders' method, whose default first
// step is 0.01 * 2^5 = 0.32 (rad or m): far enough to move a point into
// another cell. Start at 1e-5 * 2^5 instead (a few mm at most), so that the
// lookup of a point well inside its cell never changes during the check.
ceres::NumericDiffOptions SmallStepOptions() {
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-5;
  return options;
}

Vector6d TestPose() {
  Vector6d xi;
  xi << 0.2, -0.1, 0.05, 0.1, -0.05, 0.2;
  return xi;
}

// The input point that `xi` maps to `reference_point`.
Vector3d InputPointFor(const Vector6d& xi, const Vector3d& reference_point) {
  return ElementaryProduct(xi(3), xi(4), xi(5)).transpose() *
         (reference_point - xi.head<3>());
}

Eigen::Quaterniond QuaternionOf(const Vector6d& xi) {
  return Eigen::Quaterniond(EulerRotation(xi(3), xi(4), xi(5)));
}

// Residual (and optionally the Jacobian) of a 6-vector cost, pre-filled with
// NaN.
Vector3d EvaluateSixVector(
    const ceres::CostFunction& cost,
    const Vector6d& xi,
    Eigen::Matrix<double, 3, 6, Eigen::RowMajor>* jacobian = nullptr) {
  Vector3d residual = Vector3d::Constant(kNaN);
  const double* parameters[] = {xi.data()};
  double* jacobians[] = {jacobian != nullptr ? jacobian->data() : nullptr};
  if (jacobian != nullptr) jacobian->setConstant(kNaN);
  EXPECT_TRUE(cost.Evaluate(
      parameters, residual.data(), jacobian != nullptr ? jacobians : nullptr));
  return residual;
}

Vector3d EvaluateQuaternion(const ceres::CostFunction& cost,
                            const Eigen::Quaterniond& q,
                            const Vector3d& t) {
  Vector3d residual = Vector3d::Constant(kNaN);
  const double* parameters[] = {q.coeffs().data(), t.data()};
  EXPECT_TRUE(cost.Evaluate(parameters, residual.data(), nullptr));
  return residual;
}

TEST(MlNdtPointCost, ResidualIsWhitenedErrorAtHandComputedConfiguration) {
  const HandLayer hand;
  // The regularisation kept the covariance (all eigenvalues above the floors).
  ASSERT_TRUE(EigenNear(hand.a().covariance, hand.cov_a, 1e-12));
  const Vector6d xi = TestPose();
  const Vector3d p = InputPointFor(xi, Vector3d(2.8, 3.3, 1.1));
  std::unique_ptr<ceres::CostFunction> cost(
      MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
  ASSERT_EQ(cost->num_residuals(), 3);
  ASSERT_EQ(cost->parameter_block_sizes(), std::vector<int32_t>({6}));

  const Vector3d residual = EvaluateSixVector(*cost, xi);
  const Vector3d e =
      ElementaryProduct(xi(3), xi(4), xi(5)) * p + xi.head<3>() - hand.mean_a;
  EXPECT_TRUE(EigenNear(e, Vector3d(2.8, 3.3, 1.1) - hand.mean_a, 1e-12));
  EXPECT_TRUE(EigenNear(residual, hand.a().whitening * e, 1e-12));
  // ||r||^2 = e^T C^-1 e (Eq. 10), with C^-1 computed independently.
  EXPECT_NEAR(residual.squaredNorm(), e.dot(hand.cov_a.inverse() * e), 1e-12);
  // Not a diagonal weighting: the whitening mixes the axes.
  const Vector3d diagonal_only =
      hand.cov_a.diagonal().cwiseInverse().cwiseSqrt().cwiseProduct(e);
  EXPECT_GT(std::abs(residual.squaredNorm() - diagonal_only.squaredNorm()),
            1e-3);
}

TEST(MlNdtPointCost, BoundCostFollowsTheBindingsLayer) {
  const HandLayer hand;
  // Same grid, no occupied cell: every residual is zero there.
  const NdtLayer empty(Vector3d::Zero(), 2.0, Eigen::Vector3i(4, 3, 2), {}, {});
  const Vector6d xi = TestPose();
  const Vector3d p = InputPointFor(xi, Vector3d(2.8, 3.3, 1.1));  // Inside A.
  std::unique_ptr<ceres::CostFunction> fixed(
      MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
  LayerBinding binding(hand.layer);
  std::unique_ptr<ceres::CostFunction> bound(
      MlNdtPointCost::Create(binding, p, UnmatchedPolicy::ZERO_RESIDUAL));
  const Vector3d on_hand = EvaluateSixVector(*fixed, xi);
  ASSERT_GT(on_hand.norm(), 0.1);
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*bound, xi), on_hand, 0.0));
  binding.Rebind(empty);
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*bound, xi), Vector3d::Zero(), 0.0));
  binding.Rebind(hand.layer);
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*bound, xi), on_hand, 0.0));
}

TEST(MlNdtPointCostQuaternion,
     ResidualIsWhitenedErrorAtHandComputedConfiguration) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const Vector3d target(6.5, 2.4, 3.6);  // Inside B.
  const Vector3d p = InputPointFor(xi, target);
  std::unique_ptr<ceres::CostFunction> cost(MlNdtPointCostQuaternion::Create(
      hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
  ASSERT_EQ(cost->num_residuals(), 3);
  ASSERT_EQ(cost->parameter_block_sizes(), std::vector<int32_t>({4, 3}));
  const Eigen::Quaterniond q(ElementaryProduct(xi(3), xi(4), xi(5)));
  const Vector3d t = xi.head<3>();
  const Vector3d residual = EvaluateQuaternion(*cost, q, t);
  const Vector3d e = target - hand.mean_b;
  EXPECT_TRUE(EigenNear(residual, hand.b().whitening * e, 1e-12));
  EXPECT_NEAR(residual.squaredNorm(), e.dot(hand.cov_b.inverse() * e), 1e-12);
}

TEST(MlNdtPointCost, GradientCheckerAgrees) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const ceres::NumericDiffOptions numeric_options = SmallStepOptions();
  // Points well inside A, B and C, so that no finite-difference step changes
  // the cell.
  for (const Vector3d& target : {Vector3d(2.8, 3.3, 1.1),
                                 Vector3d(6.5, 2.4, 3.6),
                                 Vector3d(5.0, 4.9, 0.7)}) {
    const Vector3d p = InputPointFor(xi, target);
    std::unique_ptr<ceres::CostFunction> cost(
        MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
    const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
    ceres::GradientChecker checker(cost.get(), no_manifolds, numeric_options);
    ceres::GradientChecker::ProbeResults results;
    const double* parameters[] = {xi.data()};
    EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
    // A non-trivial Jacobian: the check is not comparing zeros.
    EXPECT_GT(results.jacobians[0].norm(), 1.0);
  }
}

TEST(MlNdtPointCostQuaternion, GradientCheckerAgreesWithQuaternionManifold) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const Eigen::Quaterniond q = QuaternionOf(xi);
  const Vector3d t = xi.head<3>();
  ceres::EigenQuaternionManifold quaternion_manifold;
  const std::vector<const ceres::Manifold*> manifolds = {&quaternion_manifold,
                                                         nullptr};
  const ceres::NumericDiffOptions numeric_options = SmallStepOptions();
  for (const Vector3d& target : {Vector3d(2.8, 3.3, 1.1),
                                 Vector3d(6.5, 2.4, 3.6),
                                 Vector3d(5.0, 4.9, 0.7)}) {
    const Vector3d p = InputPointFor(xi, target);
    std::unique_ptr<ceres::CostFunction> cost(MlNdtPointCostQuaternion::Create(
        hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
    ceres::GradientChecker checker(cost.get(), &manifolds, numeric_options);
    ceres::GradientChecker::ProbeResults results;
    const double* parameters[] = {q.coeffs().data(), t.data()};
    EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
    ASSERT_EQ(results.local_jacobians.size(), 2u);
    EXPECT_EQ(results.local_jacobians[0].cols(),
              3);  // Tangent space of the quaternion.
    EXPECT_GT(results.local_jacobians[0].norm(), 1.0);
    // d r / d t = W of the cell.
    const NdtCell* cell = hand.layer.Lookup(target);
    ASSERT_NE(cell, nullptr);
    EXPECT_TRUE(EigenNear(results.jacobians[1], cell->whitening, 1e-12));
  }
}

TEST(MlNdtPointCost, GradientCheckerAgreesForNearestCellInEmptyCell) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const Vector3d p =
      InputPointFor(xi, Vector3d(5.0, 3.8, 1.0));  // Empty cell (2, 1, 0).
  std::unique_ptr<ceres::CostFunction> cost(
      MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::NEAREST_CELL));
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  ceres::GradientChecker checker(cost.get(), no_manifolds, SmallStepOptions());
  ceres::GradientChecker::ProbeResults results;
  const double* parameters[] = {xi.data()};
  EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
  EXPECT_GT(results.jacobians[0].norm(), 1.0);
}

TEST(MlNdtPointCost, EmptyCellGivesZeroOrNearestNeighbourResidual) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const Vector3d target(5.0, 3.8, 1.0);  // Empty cell (2, 1, 0).
  ASSERT_EQ(hand.layer.Lookup(target), nullptr);
  const Vector3d p = InputPointFor(xi, target);

  // ZERO_RESIDUAL: zero residual and zero Jacobian.
  std::unique_ptr<ceres::CostFunction> zero(
      MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
  Eigen::Matrix<double, 3, 6, Eigen::RowMajor> jacobian;
  EXPECT_TRUE(EigenNear(
      EvaluateSixVector(*zero, xi, &jacobian), Vector3d::Zero(), 0.0));
  EXPECT_TRUE(EigenNear(jacobian, Eigen::Matrix<double, 3, 6>::Zero(), 0.0));

  // NEAREST_CELL: the neighbour with the smallest e^T C^-1 e, here C (not
  // the first neighbour visited, which is A), computed independently.
  const auto mahalanobis =
      [](const Vector3d& x, const Vector3d& mean, const Matrix3d& cov) {
        const Vector3d e = x - mean;
        return e.dot(cov.inverse() * e);
      };
  const double to_a = mahalanobis(target, hand.mean_a, hand.cov_a);
  const double to_b = mahalanobis(target, hand.mean_b, hand.cov_b);
  const double to_c = mahalanobis(target, hand.mean_c, hand.cov_c);
  ASSERT_LT(to_c, to_a);
  ASSERT_LT(to_c, to_b);
  std::unique_ptr<ceres::CostFunction> nearest(
      MlNdtPointCost::Create(hand.layer, p, UnmatchedPolicy::NEAREST_CELL));
  const Vector3d residual = EvaluateSixVector(*nearest, xi, &jacobian);
  EXPECT_TRUE(
      EigenNear(residual, hand.c().whitening * (target - hand.mean_c), 1e-12));
  EXPECT_NEAR(residual.squaredNorm(), to_c, 1e-10);
  // d r / d t = W_C.
  EXPECT_TRUE(
      EigenNear(Matrix3d(jacobian.leftCols<3>()), hand.c().whitening, 1e-12));

  // Moved next to A instead, the same empty cell matches A.
  const Vector3d near_a(4.1, 2.9, 0.8);
  ASSERT_EQ(hand.layer.Lookup(near_a), nullptr);
  ASSERT_LT(mahalanobis(near_a, hand.mean_a, hand.cov_a),
            mahalanobis(near_a, hand.mean_b, hand.cov_b));
  ASSERT_LT(mahalanobis(near_a, hand.mean_a, hand.cov_a),
            mahalanobis(near_a, hand.mean_c, hand.cov_c));
  std::unique_ptr<ceres::CostFunction> nearest_a(MlNdtPointCost::Create(
      hand.layer, InputPointFor(xi, near_a), UnmatchedPolicy::NEAREST_CELL));
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*nearest_a, xi),
                        hand.a().whitening * (near_a - hand.mean_a),
                        1e-12));
}

TEST(MlNdtPointCost, PointOutsideTheGridGivesZeroResidual) {
  const HandLayer hand;
  const Vector6d xi = TestPose();
  // Far outside, with no occupied cell around the grid cell it clamps to.
  for (const Vector3d& target : {Vector3d(-50.0, 3.0, 1.0),
                                 Vector3d(30.0, -40.0, 50.0),
                                 Vector3d(0.5, 30.0, 3.0),
                                 Vector3d(-1.0, -1.0, -1.0)}) {
    for (const UnmatchedPolicy policy :
         {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
      std::unique_ptr<ceres::CostFunction> cost(MlNdtPointCost::Create(
          hand.layer, InputPointFor(xi, target), policy));
      Eigen::Matrix<double, 3, 6, Eigen::RowMajor> jacobian;
      EXPECT_TRUE(EigenNear(
          EvaluateSixVector(*cost, xi, &jacobian), Vector3d::Zero(), 0.0))
          << target.transpose() << " " << UnmatchedPolicyToString(policy);
      EXPECT_TRUE(
          EigenNear(jacobian, Eigen::Matrix<double, 3, 6>::Zero(), 0.0));
    }
  }
  // Far below occupied cell A (clamping into the grid, or to the ring of
  // cells just outside it, would land in or next to A): zero in both policies.
  for (const Vector3d& target : {Vector3d(3.0, 3.0, -30.0),
                                 Vector3d(3.0, 3.0, -2.5),
                                 Vector3d(3.0, 3.0, -1e12)}) {
    for (const UnmatchedPolicy policy :
         {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
      std::unique_ptr<ceres::CostFunction> below_a(MlNdtPointCost::Create(
          hand.layer, InputPointFor(xi, target), policy));
      EXPECT_TRUE(
          EigenNear(EvaluateSixVector(*below_a, xi), Vector3d::Zero(), 0.0))
          << target.transpose() << " " << UnmatchedPolicyToString(policy);
    }
  }
  // Just outside the grid, in the ring of cells next to A: NEAREST_CELL
  // still pulls it towards A (a point just past a cell border).
  const Vector3d just_below_a(3.0, 3.0, -0.5);
  std::unique_ptr<ceres::CostFunction> zero(
      MlNdtPointCost::Create(hand.layer,
                             InputPointFor(xi, just_below_a),
                             UnmatchedPolicy::ZERO_RESIDUAL));
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*zero, xi), Vector3d::Zero(), 0.0));
  std::unique_ptr<ceres::CostFunction> nearest(
      MlNdtPointCost::Create(hand.layer,
                             InputPointFor(xi, just_below_a),
                             UnmatchedPolicy::NEAREST_CELL));
  EXPECT_TRUE(EigenNear(EvaluateSixVector(*nearest, xi),
                        hand.a().whitening * (just_below_a - hand.mean_a),
                        1e-12));
}

TEST(MlNdtPointCost, JetScalarPartDrivesTheCellLookup) {
  using Jet = ceres::Jet<double, 3>;
  const HandLayer hand;
  // Scalar part in A; scalar + derivative parts would be far away (or in B).
  const Vector3d value(2.5, 3.0, 1.0);
  Eigen::Matrix<Jet, 3, 1> x;
  Matrix3d derivative;
  derivative << 1e6, -2e6, 3e5,  //
      4e6, 1e6, -1e6,            //
      4.0, 0.3, 2e6;
  for (int r = 0; r < 3; ++r) {
    x(r).a = value(r);
    x(r).v = derivative.row(r).transpose();
  }
  Jet residual[3];
  for (Jet& r : residual) r = Jet(kNaN);
  WhitenedCellResidual(hand.layer, UnmatchedPolicy::ZERO_RESIDUAL, x, residual);
  Vector3d scalar;
  Matrix3d residual_derivative;
  for (int r = 0; r < 3; ++r) {
    scalar(r) = residual[r].a;
    residual_derivative.row(r) = residual[r].v.transpose();
  }
  EXPECT_TRUE(
      EigenNear(scalar, hand.a().whitening * (value - hand.mean_a), 1e-12));
  EXPECT_TRUE(
      EigenNear(residual_derivative, hand.a().whitening * derivative, 1e-6));
}

TEST(MlNdtPointCost, JetWithHugeDerivativesMatchesDoubleEvaluation) {
  using Jet = ceres::Jet<double, 6>;
  const HandLayer hand;
  const Vector6d xi = TestPose();
  const Vector3d target(2.8, 3.3, 1.1);
  const MlNdtPointCost functor(
      hand.layer, InputPointFor(xi, target), UnmatchedPolicy::ZERO_RESIDUAL);
  Jet xi_jet[6];
  for (int i = 0; i < 6; ++i) {
    xi_jet[i] = Jet(xi(i), i);
    xi_jet[i].v *=
        1e9;  // Seeds scaled by 1e9: derivatives scale, lookup must not.
  }
  Jet residual[3];
  for (Jet& r : residual) r = Jet(kNaN);
  ASSERT_TRUE(functor(xi_jet, residual));
  Vector3d double_residual = Vector3d::Constant(kNaN);
  ASSERT_TRUE(functor(xi.data(), double_residual.data()));
  EXPECT_TRUE(EigenNear(
      double_residual, hand.a().whitening * (target - hand.mean_a), 1e-12));
  Eigen::Matrix<double, 3, 6> jet_jacobian;
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(residual[r].a, double_residual(r), 1e-12);
    jet_jacobian.row(r) = residual[r].v.transpose() / 1e9;
  }
  // The same Jacobian as with unit seeds, i.e. the same cell A.
  std::unique_ptr<ceres::CostFunction> cost(MlNdtPointCost::Create(
      hand.layer, InputPointFor(xi, target), UnmatchedPolicy::ZERO_RESIDUAL));
  Eigen::Matrix<double, 3, 6, Eigen::RowMajor> jacobian;
  EvaluateSixVector(*cost, xi, &jacobian);
  EXPECT_TRUE(
      EigenNear(jet_jacobian, Eigen::Matrix<double, 3, 6>(jacobian), 1e-8));
}

TEST(MlNdtPointCostQuaternion, SameResidualAsSixVectorFunctor) {
  const HandLayer hand;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> angle(-0.3, 0.3);
  std::uniform_real_distribution<double> shift(-0.3, 0.3);
  std::uniform_real_distribution<double> coordinate(0.0, 8.0);
  int nonzero = 0;
  for (int trial = 0; trial < 100; ++trial) {
    Vector6d xi;
    xi << shift(rng), shift(rng), shift(rng), angle(rng), angle(rng),
        angle(rng);
    const Vector3d p(
        coordinate(rng), 0.75 * coordinate(rng), 0.5 * coordinate(rng));
    for (const UnmatchedPolicy policy :
         {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
      std::unique_ptr<ceres::CostFunction> six(
          MlNdtPointCost::Create(hand.layer, p, policy));
      std::unique_ptr<ceres::CostFunction> quaternion(
          MlNdtPointCostQuaternion::Create(hand.layer, p, policy));
      const Vector3d r6 = EvaluateSixVector(*six, xi);
      const Vector3d rq =
          EvaluateQuaternion(*quaternion, QuaternionOf(xi), xi.head<3>());
      EXPECT_TRUE(EigenNear(rq, r6, 1e-10)) << "trial " << trial;
      if (r6.squaredNorm() > 0.0) ++nonzero;
    }
  }
  EXPECT_GT(
      nonzero,
      20);  // Enough points hit a cell for the comparison to mean something.
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

TEST(CachedEulerRotation, MatchesEulerRotationForChangingJets) {
  using Jet = ceres::Jet<double, 6>;
  const double values[][3] = {
      {0.1, -0.2, 0.3}, {0.1, -0.2, 0.3}, {0.4, 0.0, -1.0}, {0.1, -0.2, 0.3}};
  for (int seed_offset = 0; seed_offset < 2; ++seed_offset) {
    for (const auto& v : values) {
      Jet angles[3];
      for (int i = 0; i < 3; ++i) angles[i] = Jet(v[i], (i + seed_offset) % 6);
      const Eigen::Matrix<Jet, 3, 3> expected =
          EulerRotation(angles[0], angles[1], angles[2]);
      const Eigen::Matrix<Jet, 3, 3>& cached = CachedEulerRotation(angles);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          EXPECT_EQ(cached(r, c).a, expected(r, c).a);
          EXPECT_EQ(cached(r, c).v, expected(r, c).v);  // Derivative parts too.
        }
      }
    }
  }
  const double plain[3] = {0.7, 0.1, -0.3};
  EXPECT_EQ(CachedEulerRotation(plain),
            EulerRotation(plain[0], plain[1], plain[2]));
}

// The Jet versions of CachedTransformPoint and WhitenedCellResidual skip
// the products with a constant's zero derivative part: the residual's
// scalar part keeps its bits and the derivatives their values (== also
// equates a zero's two signs), against Eigen's products with the constants
// cast to Jets (the generic versions' expressions).
TEST(JetTimesConstant, SameValuesAsTheGenericJetProducts) {
  using Jet = ceres::Jet<double, 6>;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    Jet xi[6];
    for (int i = 0; i < 6; ++i) {
      xi[i] = Jet(u(rng) * (i < 3 ? 1.0 : 0.5), i);
      xi[i].v(trial % 6) += u(rng);  // Derivative parts of any shape.
    }
    const Eigen::Vector3d x(u(rng) * 20.0, u(rng) * 20.0, u(rng));
    const Eigen::Matrix<Jet, 3, 1> fast = CachedTransformPoint(xi, x);
    const Eigen::Matrix<Jet, 3, 1> generic =
        CachedEulerRotation(xi + 3) * x.cast<Jet>() +
        Eigen::Matrix<Jet, 3, 1>(xi[0], xi[1], xi[2]);
    Eigen::Matrix3d w;
    w << u(rng), u(rng), u(rng), 0.0, u(rng), u(rng), 0.0, 0.0, u(rng);
    const Eigen::Vector3d mu(u(rng), u(rng), u(rng));
    Eigen::Matrix<Jet, 3, 1> e = fast;
    for (int i = 0; i < 3; ++i) e(i).a -= mu(i);
    const Eigen::Matrix<Jet, 3, 1> r = JetTimesConstant(w, e);
    const Eigen::Matrix<Jet, 3, 1> r_generic =
        w.cast<Jet>() * (generic - mu.cast<Jet>());
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(SameBits(fast(i).a, generic(i).a)) << "trial " << trial;
      EXPECT_EQ(fast(i).v, generic(i).v) << "trial " << trial;
      EXPECT_TRUE(SameBits(r(i).a, r_generic(i).a)) << "trial " << trial;
      EXPECT_EQ(r(i).v, r_generic(i).v) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace mlndt
