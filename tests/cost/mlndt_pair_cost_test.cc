// Tests of MlNdtPairCost (mlndt_pair_cost.h), MlNdtPairCostAnalytic
// (mlndt_pair_cost_analytic.h) and AddMlNdtPairResiduals
// (add_pair_residuals.h).

#include "mlndt/cost/mlndt_pair_cost.h"

#include <ceres/ceres.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>
#include <ceres/numeric_diff_options.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/cost/mlndt_pair_cost_analytic.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/synthetic_scene.h"
#include "tests/testing/tilted_cells.h"

namespace mlndt {
namespace {

using testing::TiltedCovariance;

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::EigenNear;

// Q diag(l) Q^T with a tilted Q: non-diagonal, eigenvalues above the floors.
// A hand-built layer of scan i's map: origin 0, 2 m cells, 4 x 3 x 2 grid,
// occupied cells A at (1, 1, 0) and B at (3, 1, 1); cell (2, 1, 0) is empty
// with A as a neighbour.
struct HandLayer {
  Vector3d mean_a{3.1, 2.9, 0.8};
  Vector3d mean_b{7.0, 3.2, 2.9};
  Matrix3d cov_a = TiltedCovariance({0.40, 0.15, 0.05}, 0.7, {1.0, 2.0, -0.5});
  Matrix3d cov_b = TiltedCovariance({0.30, 0.20, 0.02}, 1.1, {-0.3, 1.0, 1.0});
  NdtLayer layer;

  HandLayer() {
    const auto key = [](int i, int j, int k) -> int64_t {
      return i + 4 * (j + 3 * k);
    };
    std::vector<NdtCell> cells(2);
    EXPECT_TRUE(
        MakeNdtCell(20, mean_a, cov_a, CellRegularization(), &cells[0]));
    EXPECT_TRUE(
        MakeNdtCell(20, mean_b, cov_b, CellRegularization(), &cells[1]));
    layer = NdtLayer(Vector3d::Zero(),
                     2.0,
                     Eigen::Vector3i(4, 3, 2),
                     cells,
                     {key(1, 1, 0), key(3, 1, 1)});
  }
  const NdtCell& a() const { return *layer.CellAt({1, 1, 0}); }
  const NdtCell& b() const { return *layer.CellAt({3, 1, 1}); }
};

// A world_from_scan pose as quaternion (x, y, z, w) + translation.
struct Pose {
  Quaterniond rotation;
  Vector3d translation;

  Eigen::Isometry3d Isometry() const {
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = rotation.toRotationMatrix();
    out.translation() = translation;
    return out;
  }
  static Pose From(const Eigen::Isometry3d& transform) {
    return {Quaterniond(transform.linear()).normalized(),
            transform.translation()};
  }
};

Quaterniond RotationFromAngleAxis(double angle, const Vector3d& axis) {
  return Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

Pose PoseI() {
  return {RotationFromAngleAxis(0.6, {0.3, -0.5, 1.0}),
          Vector3d(12.0, -4.0, 1.5)};
}
Pose PoseJ() {
  return {RotationFromAngleAxis(0.7, {0.2, -0.4, 1.0}),
          Vector3d(13.1, -3.2, 1.4)};
}

// The point of scan j that the poses map to `in_scan_i` (scan i's frame).
Vector3d InputPointFor(const Pose& pose_i,
                       const Pose& pose_j,
                       const Vector3d& in_scan_i) {
  return (pose_j.Isometry().inverse() * pose_i.Isometry()) * in_scan_i;
}

// Residual of a pair cost, pre-filled with NaN so unwritten entries show.
Vector3d EvaluatePair(const ceres::CostFunction& cost,
                      const Pose& pose_i,
                      const Pose& pose_j) {
  Vector3d residual = Vector3d::Constant(kNaN);
  const double* parameters[] = {pose_i.rotation.coeffs().data(),
                                pose_i.translation.data(),
                                pose_j.rotation.coeffs().data(),
                                pose_j.translation.data()};
  EXPECT_TRUE(cost.Evaluate(parameters, residual.data(), nullptr));
  return residual;
}

ceres::NumericDiffOptions SmallStepOptions() {
  // Ridders' default first step (0.32 m or rad) moves points across cells.
  ceres::NumericDiffOptions options;
  options.ridders_relative_initial_step_size = 1e-5;
  return options;
}

TEST(MlNdtPairCost, ResidualIsWhitenedErrorAtHandComputedConfiguration) {
  const HandLayer hand;
  const Pose pose_i = PoseI();
  const Pose pose_j = PoseJ();
  for (const auto& [target, cell, cov] :
       {std::make_tuple(Vector3d(2.8, 3.3, 1.1), &hand.a(), hand.cov_a),
        std::make_tuple(Vector3d(6.5, 2.4, 3.6), &hand.b(), hand.cov_b)}) {
    const Vector3d p = InputPointFor(pose_i, pose_j, target);
    // The chain p -> world -> scan i, written out with rotation matrices.
    const Vector3d world =
        pose_j.rotation.toRotationMatrix() * p + pose_j.translation;
    const Vector3d x = pose_i.rotation.toRotationMatrix().transpose() *
                       (world - pose_i.translation);
    ASSERT_TRUE(EigenNear(x, target, 1e-12));
    std::unique_ptr<ceres::CostFunction> cost(
        MlNdtPairCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
    ASSERT_EQ(cost->num_residuals(), 3);
    ASSERT_EQ(cost->parameter_block_sizes(),
              std::vector<int32_t>({4, 3, 4, 3}));
    const Vector3d residual = EvaluatePair(*cost, pose_i, pose_j);
    const Vector3d e = target - cell->mean;
    EXPECT_TRUE(EigenNear(residual, cell->whitening * e, 1e-11));
    // ||r||^2 = e^T C^-1 e with the (non-diagonal) C inverted independently.
    EXPECT_NEAR(residual.squaredNorm(), e.dot(cov.inverse() * e), 1e-10);
  }
}

TEST(MlNdtPairCost, GradientCheckerAgreesWithQuaternionManifolds) {
  const HandLayer hand;
  const Pose pose_i = PoseI();
  const Pose pose_j = PoseJ();
  ceres::EigenQuaternionManifold quaternion_manifold;
  const std::vector<const ceres::Manifold*> manifolds = {
      &quaternion_manifold, nullptr, &quaternion_manifold, nullptr};
  // Well inside A and B, and in the empty cell next to A (NEAREST_CELL).
  for (const auto& [target, policy] :
       {std::make_pair(Vector3d(2.8, 3.3, 1.1), UnmatchedPolicy::ZERO_RESIDUAL),
        std::make_pair(Vector3d(6.5, 2.4, 3.6), UnmatchedPolicy::ZERO_RESIDUAL),
        std::make_pair(Vector3d(4.6, 3.0, 1.0),
                       UnmatchedPolicy::NEAREST_CELL)}) {
    SCOPED_TRACE(UnmatchedPolicyToString(policy));
    const Vector3d p = InputPointFor(pose_i, pose_j, target);
    std::unique_ptr<ceres::CostFunction> cost(
        MlNdtPairCost::Create(hand.layer, p, policy));
    ceres::GradientChecker checker(cost.get(), &manifolds, SmallStepOptions());
    ceres::GradientChecker::ProbeResults results;
    const double* parameters[] = {pose_i.rotation.coeffs().data(),
                                  pose_i.translation.data(),
                                  pose_j.rotation.coeffs().data(),
                                  pose_j.translation.data()};
    EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
    ASSERT_EQ(results.local_jacobians.size(), 4u);
    for (int block = 0; block < 4; ++block) {
      // Tangent spaces are 3-dimensional; no block compares zeros.
      EXPECT_EQ(results.local_jacobians[block].cols(), 3);
      EXPECT_GT(results.local_jacobians[block].norm(), 1.0)
          << "block " << block;
    }
    // d r / d t_j = W R_i^T, d r / d t_i = -W R_i^T.
    const NdtCell* cell = MatchCell(hand.layer, target, policy);
    ASSERT_NE(cell, nullptr);
    const Matrix3d w_rt =
        cell->whitening * pose_i.rotation.toRotationMatrix().transpose();
    EXPECT_TRUE(EigenNear(results.jacobians[3], w_rt, 1e-10));
    EXPECT_TRUE(EigenNear(results.jacobians[1], Matrix3d(-w_rt), 1e-10));
  }
}

TEST(MlNdtPairCostAnalytic, EqualsAutoDiffResidualAndAmbientJacobians) {
  const HandLayer hand;
  const Pose pose_i = PoseI();
  // A quaternion off the unit sphere too: both extend Eigen's product the
  // same way, so even the ambient Jacobians agree there.
  Pose pose_j_off = PoseJ();
  pose_j_off.rotation.coeffs() *= 1.03;
  // In A, in B, next to A (NEAREST_CELL), and outside every cell.
  for (const bool on_sphere : {true, false}) {
    const Pose pose_j = on_sphere ? PoseJ() : pose_j_off;
    for (const auto& [target, policy] :
         {std::make_pair(Vector3d(2.8, 3.3, 1.1),
                         UnmatchedPolicy::ZERO_RESIDUAL),
          std::make_pair(Vector3d(6.5, 2.4, 3.6),
                         UnmatchedPolicy::ZERO_RESIDUAL),
          std::make_pair(Vector3d(4.6, 3.0, 1.0),
                         UnmatchedPolicy::NEAREST_CELL),
          std::make_pair(Vector3d(4.6, 3.0, 1.0),
                         UnmatchedPolicy::ZERO_RESIDUAL)}) {
      SCOPED_TRACE(UnmatchedPolicyToString(policy));
      const Vector3d p = InputPointFor(pose_i, PoseJ(), target);
      std::unique_ptr<ceres::CostFunction> autodiff(
          MlNdtPairCost::Create(hand.layer, p, policy));
      const MlNdtPairCostAnalytic analytic(hand.layer, p, policy);
      ASSERT_EQ(analytic.parameter_block_sizes(),
                autodiff->parameter_block_sizes());
      const double* parameters[] = {pose_i.rotation.coeffs().data(),
                                    pose_i.translation.data(),
                                    pose_j.rotation.coeffs().data(),
                                    pose_j.translation.data()};
      const int sizes[] = {4, 3, 4, 3};
      std::vector<std::vector<double>> expected(4), actual(4);
      double* expected_ptrs[4];
      double* actual_ptrs[4];
      for (int b = 0; b < 4; ++b) {
        expected[b].assign(3 * sizes[b], kNaN);
        actual[b].assign(3 * sizes[b], kNaN);
        expected_ptrs[b] = expected[b].data();
        actual_ptrs[b] = actual[b].data();
      }
      Vector3d r_expected = Vector3d::Constant(kNaN);
      Vector3d r_actual = Vector3d::Constant(kNaN);
      ASSERT_TRUE(
          autodiff->Evaluate(parameters, r_expected.data(), expected_ptrs));
      ASSERT_TRUE(analytic.Evaluate(parameters, r_actual.data(), actual_ptrs));
      EXPECT_TRUE(EigenNear(r_actual, r_expected, 1e-12));
      double jacobian_norm = 0.0;
      for (int b = 0; b < 4; ++b) {
        for (size_t k = 0; k < expected[b].size(); ++k) {
          EXPECT_NEAR(actual[b][k], expected[b][k], 1e-10)
              << "block " << b << " entry " << k;
          jacobian_norm += std::abs(expected[b][k]);
        }
      }
      // On the sphere the targets are where they say: only the point
      // outside every cell under ZERO_RESIDUAL has zero Jacobians.
      const bool unmatched =
          target.x() == 4.6 && policy == UnmatchedPolicy::ZERO_RESIDUAL;
      if (on_sphere) EXPECT_EQ(jacobian_norm == 0.0, unmatched);
    }
  }
}

TEST(MlNdtPairCost, EqualsSinglePoseResidualWhenPoseIIsIdentity) {
  const HandLayer hand;
  const Pose identity{Quaterniond::Identity(), Vector3d::Zero()};
  const Pose pose_j = PoseJ();
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    for (const Vector3d& target : {Vector3d(2.8, 3.3, 1.1),
                                   Vector3d(6.5, 2.4, 3.6),
                                   Vector3d(4.6, 3.0, 1.0),
                                   Vector3d(-20.0, 3.0, 1.0)}) {
      SCOPED_TRACE(UnmatchedPolicyToString(policy));
      const Vector3d p = InputPointFor(identity, pose_j, target);
      std::unique_ptr<ceres::CostFunction> pair(
          MlNdtPairCost::Create(hand.layer, p, policy));
      std::unique_ptr<ceres::CostFunction> single(
          MlNdtPointCostQuaternion::Create(hand.layer, p, policy));
      Vector3d expected = Vector3d::Constant(kNaN);
      const double* single_parameters[] = {pose_j.rotation.coeffs().data(),
                                           pose_j.translation.data()};
      Eigen::Matrix<double, 3, 4, Eigen::RowMajor> single_dq, pair_dq;
      Eigen::Matrix<double, 3, 3, Eigen::RowMajor> single_dt, pair_dt;
      double* single_jacobians[] = {single_dq.data(), single_dt.data()};
      ASSERT_TRUE(single->Evaluate(
          single_parameters, expected.data(), single_jacobians));

      Vector3d residual = Vector3d::Constant(kNaN);
      Eigen::Matrix<double, 3, 4, Eigen::RowMajor> dq_i;
      Eigen::Matrix<double, 3, 3, Eigen::RowMajor> dt_i;
      const double* pair_parameters[] = {identity.rotation.coeffs().data(),
                                         identity.translation.data(),
                                         pose_j.rotation.coeffs().data(),
                                         pose_j.translation.data()};
      double* pair_jacobians[] = {
          dq_i.data(), dt_i.data(), pair_dq.data(), pair_dt.data()};
      ASSERT_TRUE(
          pair->Evaluate(pair_parameters, residual.data(), pair_jacobians));
      EXPECT_TRUE(EigenNear(residual, expected, 1e-12)) << target.transpose();
      // Pose j's derivatives are those of the single-pose functor.
      EXPECT_TRUE(EigenNear(pair_dq, single_dq, 1e-12));
      EXPECT_TRUE(EigenNear(pair_dt, single_dt, 1e-12));
    }
  }
}

TEST(MlNdtPairCost, InvariantToACommonWorldTransform) {
  const HandLayer hand;
  const Pose pose_i = PoseI();
  const Pose pose_j = PoseJ();
  Eigen::Isometry3d world2_from_world = Eigen::Isometry3d::Identity();
  world2_from_world.linear() =
      RotationFromAngleAxis(2.1, {-0.7, 0.4, 0.2}).toRotationMatrix();
  world2_from_world.translation() = Vector3d(-150.0, 320.0, -12.0);
  const Pose moved_i = Pose::From(world2_from_world * pose_i.Isometry());
  const Pose moved_j = Pose::From(world2_from_world * pose_j.Isometry());
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    for (const Vector3d& target : {Vector3d(2.8, 3.3, 1.1),
                                   Vector3d(6.5, 2.4, 3.6),
                                   Vector3d(4.6, 3.0, 1.0)}) {
      const Vector3d p = InputPointFor(pose_i, pose_j, target);
      std::unique_ptr<ceres::CostFunction> cost(
          MlNdtPairCost::Create(hand.layer, p, policy));
      const Vector3d before = EvaluatePair(*cost, pose_i, pose_j);
      const Vector3d after = EvaluatePair(*cost, moved_i, moved_j);
      // Non-zero except for the empty cell under ZERO_RESIDUAL.
      const bool in_empty_cell = hand.layer.Lookup(target) == nullptr;
      if (policy == UnmatchedPolicy::NEAREST_CELL || !in_empty_cell) {
        EXPECT_GT(before.norm(), 0.1) << UnmatchedPolicyToString(policy);
      }
      EXPECT_TRUE(EigenNear(after, before, 1e-9))
          << UnmatchedPolicyToString(policy);
    }
  }
  // Moving only one of the two poses changes the residual.
  const Vector3d p = InputPointFor(pose_i, pose_j, Vector3d(2.8, 3.3, 1.1));
  std::unique_ptr<ceres::CostFunction> cost(
      MlNdtPairCost::Create(hand.layer, p, UnmatchedPolicy::ZERO_RESIDUAL));
  const Pose shifted_j{pose_j.rotation,
                       pose_j.translation + Vector3d(0.2, 0.0, 0.0)};
  EXPECT_GT((EvaluatePair(*cost, pose_i, shifted_j) -
             EvaluatePair(*cost, pose_i, pose_j))
                .norm(),
            0.01);
}

TEST(AddMlNdtPairResiduals, AddsOneBlockPerPointAndSetsQuaternionManifolds) {
  const HandLayer hand;
  Pose pose_i = PoseI();
  Pose pose_j = PoseJ();
  const std::vector<Vector3d> points = {Vector3d(1.0, 0.0, 0.0),
                                        Vector3d(0.0, 2.0, 0.5),
                                        Vector3d(0.5, 0.5, 0.5)};
  ceres::Problem problem;
  const std::vector<ceres::ResidualBlockId> ids =
      AddMlNdtPairResiduals(hand.layer,
                            points,
                            PaperObjectiveOptions(),
                            pose_i.rotation.coeffs().data(),
                            pose_i.translation.data(),
                            pose_j.rotation.coeffs().data(),
                            pose_j.translation.data(),
                            &problem);
  EXPECT_EQ(ids.size(), points.size());
  EXPECT_EQ(problem.NumResidualBlocks(), 3);
  EXPECT_EQ(problem.NumParameterBlocks(), 4);
  EXPECT_NE(dynamic_cast<const ceres::EigenQuaternionManifold*>(
                problem.GetManifold(pose_i.rotation.coeffs().data())),
            nullptr);
  EXPECT_NE(dynamic_cast<const ceres::EigenQuaternionManifold*>(
                problem.GetManifold(pose_j.rotation.coeffs().data())),
            nullptr);
  EXPECT_EQ(problem.GetManifold(pose_i.translation.data()), nullptr);
  EXPECT_EQ(problem.ParameterBlockTangentSize(pose_j.rotation.coeffs().data()),
            3);
}

TEST(AddMlNdtPairResiduals, KeepsTheCallersManifold) {
  const HandLayer hand;
  Pose pose_i = PoseI();
  Pose pose_j = PoseJ();
  ceres::Problem problem;
  problem.AddParameterBlock(
      pose_i.rotation.coeffs().data(), 4, new ceres::QuaternionManifold);
  auto* callers = problem.GetManifold(pose_i.rotation.coeffs().data());
  AddMlNdtPairResiduals(hand.layer,
                        {Vector3d(1.0, 0.0, 0.0)},
                        PaperObjectiveOptions(),
                        pose_i.rotation.coeffs().data(),
                        pose_i.translation.data(),
                        pose_j.rotation.coeffs().data(),
                        pose_j.translation.data(),
                        &problem);
  EXPECT_EQ(problem.GetManifold(pose_i.rotation.coeffs().data()), callers);
}

// A joint solve on a synthetic street: two scans of the same surfaces with
// known world_from_scan poses. Scan 0's pose is fixed at a non-identity world
// pose; scan 1 starts pushed off and must return to its true pose.
TEST(AddMlNdtPairResiduals, JointSolveRecoversTheRelativePose) {
  Eigen::Isometry3d world_from_scan0 = Eigen::Isometry3d::Identity();
  world_from_scan0.linear() =
      RotationFromAngleAxis(0.4, {0.0, 0.0, 1.0}).toRotationMatrix();
  world_from_scan0.translation() = Vector3d(100.0, -50.0, 2.0);
  Eigen::Isometry3d scan0_from_scan1 = Eigen::Isometry3d::Identity();
  scan0_from_scan1.linear() =
      RotationFromAngleAxis(0.05, {0.1, 0.0, 1.0}).toRotationMatrix();
  scan0_from_scan1.translation() = Vector3d(1.5, 0.3, 0.05);
  const Eigen::Isometry3d world_from_scan1 =
      world_from_scan0 * scan0_from_scan1;

  // Both scans sample the street in its own frame; scan 1's points are moved
  // into scan 1's frame.
  const PointCloud scene0 = testing::StreetScene(60000, 0.02, 11);
  const PointCloud scene1 = testing::StreetScene(60000, 0.02, 12);
  std::vector<Vector3d> scan1_points;
  for (const Vector3d& p : scene1.points())
    scan1_points.push_back(scan0_from_scan1.inverse() * p);
  PointCloud scan1(scan1_points);
  LayeredGridOptions grid_options;
  grid_options.finest_cell_size_m = 2.0;
  LayeredGrid map0;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(grid_options, scene0, &map0, &error)) << error;
  PointCloud samples;
  ASSERT_TRUE(SamplePoints(SamplingOptions(), scan1, &samples, nullptr, &error))
      << error;

  Pose pose0 = Pose::From(world_from_scan0);
  Eigen::Isometry3d push = Eigen::Isometry3d::Identity();
  push.linear() =
      RotationFromAngleAxis(0.03, {0.0, 0.2, 1.0}).toRotationMatrix();
  push.translation() = Vector3d(0.4, -0.3, 0.1);
  Pose pose1 = Pose::From(world_from_scan1 * push);
  for (int layer = map0.num_layers() - 1; layer <= map0.num_layers(); ++layer) {
    ceres::Problem problem;
    const ObjectiveOptions residual_options;  // Nearest cell, Cauchy 3.
    AddMlNdtPairResiduals(map0.layer(layer),
                          samples.points(),
                          residual_options,
                          pose0.rotation.coeffs().data(),
                          pose0.translation.data(),
                          pose1.rotation.coeffs().data(),
                          pose1.translation.data(),
                          &problem);
    problem.SetParameterBlockConstant(pose0.rotation.coeffs().data());
    problem.SetParameterBlockConstant(pose0.translation.data());
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 30;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  }
  // Pose 0 did not move; pose 1 is back at its true pose.
  EXPECT_TRUE(
      EigenNear(pose0.translation, world_from_scan0.translation(), 0.0));
  const Eigen::Isometry3d estimate = pose1.Isometry();
  EXPECT_LT((estimate.translation() - world_from_scan1.translation()).norm(),
            0.03);
  EXPECT_LT(Eigen::AngleAxisd(estimate.linear().transpose() *
                              world_from_scan1.linear())
                .angle(),
            0.002);
}

}  // namespace
}  // namespace mlndt
