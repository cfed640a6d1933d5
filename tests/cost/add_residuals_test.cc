#include "mlndt/cost/add_residuals.h"

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/layered_grid.h"
#include "tests/testing/eigen_near.h"
#include "tests/testing/objective.h"

namespace mlndt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using testing::EigenNear;

// A seeded synthetic room: floor, ceiling and four walls of a 10 x 8 x 4 m
// box, plus a 1 x 1 x 2 m pillar, sampled uniformly at `density` points/m^2
// with isotropic Gaussian noise of `noise_m`.
PointCloud Room(uint32_t seed, double density, double noise_m) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_m);
  PointCloud cloud;
  // A rectangle: corner + u * a + v * b, u, v in [0, 1].
  const auto add_face =
      [&](const Vector3d& corner, const Vector3d& a, const Vector3d& b) {
        const int n = static_cast<int>(density * a.cross(b).norm());
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int i = 0; i < n; ++i) {
          const Vector3d p = corner + unit(rng) * a + unit(rng) * b;
          cloud.Add(p + Vector3d(noise(rng), noise(rng), noise(rng)));
        }
      };
  const Vector3d x(10, 0, 0), y(0, 8, 0), z(0, 0, 4);
  add_face(Vector3d::Zero(), x, y);  // Floor.
  add_face(z, x, y);                 // Ceiling.
  add_face(Vector3d::Zero(), y, z);  // x = 0.
  add_face(x, y, z);                 // x = 10.
  add_face(Vector3d::Zero(), x, z);  // y = 0.
  add_face(y, x, z);                 // y = 8.
  const Vector3d pillar(3.0, 5.0, 0.0), px(1, 0, 0), py(0, 1, 0), pz(0, 0, 2);
  add_face(pillar, py, pz);
  add_face(pillar + px, py, pz);
  add_face(pillar, px, pz);
  add_face(pillar + py, px, pz);
  add_face(pillar + pz, px, py);
  return cloud;
}

// The reference map of Room(1): layers with 3.5, 1.7, 0.87 and 0.43 m cells.
const LayeredGrid& RoomGrid() {
  static const LayeredGrid* grid = [] {
    LayeredGridOptions options = PaperLayeredGridOptions();
    options.num_layers = 4;
    auto* built = new LayeredGrid;
    std::string error;
    CHECK(LayeredGrid::Build(options, Room(1, 100.0, 0.01), built, &error))
        << error;
    return built;
  }();
  return *grid;
}

// The paper-style test transform: (0.3, -0.2, 0.1 m, 2, -1, 3 deg).
Vector6d TruePose() {
  return PoseVectorFromDegrees(0.3, -0.2, 0.1, 2.0, -1.0, 3.0);
}

// Input scan: a second sampling of the room (seed 2), expressed in the input
// frame, so that TruePose() maps it onto the map. Every `stride`-th point.
std::vector<Vector3d> InputScan(int stride) {
  const PointCloud scan = Room(2, 30.0, 0.01);
  const Isometry3d input_from_reference =
      PoseVectorToIsometry(TruePose()).inverse();
  std::vector<Vector3d> points;
  for (size_t i = 0; i < scan.size(); i += static_cast<size_t>(stride)) {
    points.push_back(input_from_reference * scan[i]);
  }
  return points;
}

struct TranslationPrior {
  TranslationPrior(const Vector3d& t0, double sqrt_weight)
      : t0(t0), sqrt_weight(sqrt_weight) {}
  template <typename T>
  bool operator()(const T* xi, T* residual) const {
    for (int i = 0; i < 3; ++i) residual[i] = sqrt_weight * (xi[i] - t0(i));
    return true;
  }
  Vector3d t0;
  double sqrt_weight;
};

ceres::Solver::Options TightDenseQr() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  return options;
}

double ProblemCost(ceres::Problem* problem) {
  double cost = kNaN;
  EXPECT_TRUE(problem->Evaluate(
      ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr));
  return cost;
}

TEST(AddMlNdtResiduals, AddsOneThreeResidualBlockPerPointOnCallersPose) {
  const NdtLayer& layer = RoomGrid().layer(3);
  const std::vector<Vector3d> points = InputScan(50);
  ASSERT_GT(points.size(), 50u);
  double xi[6] = {0, 0, 0, 0, 0, 0};
  ceres::Problem problem;
  ObjectiveOptions options = PaperObjectiveOptions();
  const std::vector<ceres::ResidualBlockId> ids =
      AddMlNdtResiduals(layer, points, options, xi, &problem);
  ASSERT_EQ(ids.size(), points.size());
  EXPECT_EQ(problem.NumResidualBlocks(), static_cast<int>(points.size()));
  EXPECT_EQ(problem.NumResiduals(), 3 * static_cast<int>(points.size()));
  EXPECT_EQ(problem.NumParameterBlocks(), 1);
  EXPECT_EQ(problem.ParameterBlockSize(xi), 6);
  for (const ceres::ResidualBlockId id : ids) {
    ASSERT_NE(id, nullptr);
    const ceres::CostFunction* cost =
        problem.GetCostFunctionForResidualBlock(id);
    EXPECT_EQ(cost->num_residuals(), 3);
    std::vector<double*> blocks;
    problem.GetParameterBlocksForResidualBlock(id, &blocks);
    ASSERT_EQ(blocks.size(), 1u);
    EXPECT_EQ(blocks[0], xi);
    EXPECT_EQ(problem.GetLossFunctionForResidualBlock(id), nullptr);
  }
  EXPECT_FALSE(problem.HasManifold(xi));

  // No points: nothing added.
  ceres::Problem empty;
  EXPECT_TRUE(AddMlNdtResiduals(layer, {}, options, xi, &empty).empty());
  EXPECT_EQ(empty.NumResidualBlocks(), 0);
}

TEST(AddMlNdtResiduals, OneLossFromTheObjectiveOnEveryBlock) {
  const NdtLayer& layer = RoomGrid().layer(3);
  const std::vector<Vector3d> points = InputScan(200);
  double xi[6] = {0, 0, 0, 0, 0, 0};
  ceres::Problem problem;  // Takes ownership of the loss.
  const std::vector<ceres::ResidualBlockId> ids = AddMlNdtResiduals(
      layer,
      points,
      testing::Objective(UnmatchedPolicy::NEAREST_CELL, LossType::HUBER, 1.0),
      xi,
      &problem);
  ASSERT_FALSE(ids.empty());
  const ceres::LossFunction* loss =
      problem.GetLossFunctionForResidualBlock(ids.front());
  ASSERT_NE(loss, nullptr);
  double rho[3];
  loss->Evaluate(4.0, rho);  // Huber with scale 1 at s = 4: 2 * 2 - 1.
  EXPECT_DOUBLE_EQ(rho[0], 3.0);
  for (const ceres::ResidualBlockId id : ids) {
    EXPECT_EQ(problem.GetLossFunctionForResidualBlock(id), loss);
  }
  // The library's default objective has the Cauchy loss.
  ceres::Problem defaults;
  const std::vector<ceres::ResidualBlockId> default_ids =
      AddMlNdtResiduals(layer, points, ObjectiveOptions(), xi, &defaults);
  ASSERT_NE(defaults.GetLossFunctionForResidualBlock(default_ids.front()),
            nullptr);
  defaults.GetLossFunctionForResidualBlock(default_ids.front())
      ->Evaluate(2.25, rho);  // Cauchy, scale 1.5: 2.25 log(1 + 2.25 / 2.25).
  EXPECT_DOUBLE_EQ(rho[0], 2.25 * std::log(2.0));
}

TEST(AddMlNdtResidualsQuaternion, SetsEigenQuaternionManifoldOnRotationBlock) {
  const NdtLayer& layer = RoomGrid().layer(3);
  const std::vector<Vector3d> points = InputScan(50);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Vector3d t = Vector3d::Zero();
  ceres::Problem problem;
  const std::vector<ceres::ResidualBlockId> ids =
      AddMlNdtResidualsQuaternion(layer,
                                  points,
                                  PaperObjectiveOptions(),
                                  q.coeffs().data(),
                                  t.data(),
                                  &problem);
  ASSERT_EQ(ids.size(), points.size());
  EXPECT_EQ(problem.NumResiduals(), 3 * static_cast<int>(points.size()));
  EXPECT_EQ(problem.ParameterBlockSize(q.coeffs().data()), 4);
  EXPECT_EQ(problem.ParameterBlockSize(t.data()), 3);
  ASSERT_TRUE(problem.HasManifold(q.coeffs().data()));
  EXPECT_NE(dynamic_cast<const ceres::EigenQuaternionManifold*>(
                problem.GetManifold(q.coeffs().data())),
            nullptr);
  EXPECT_EQ(problem.ParameterBlockTangentSize(q.coeffs().data()), 3);
  EXPECT_FALSE(problem.HasManifold(t.data()));
  std::vector<double*> blocks;
  problem.GetParameterBlocksForResidualBlock(ids.front(), &blocks);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0], q.coeffs().data());
  EXPECT_EQ(blocks[1], t.data());
}

TEST(AddMlNdtResidualsQuaternion, KeepsTheCallersManifold) {
  const NdtLayer& layer = RoomGrid().layer(3);
  const std::vector<Vector3d> points = InputScan(100);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Vector3d t = Vector3d::Zero();
  ceres::Problem problem;  // Owns the manifold.
  ceres::Manifold* callers = new ceres::EigenQuaternionManifold;
  problem.AddParameterBlock(q.coeffs().data(), 4, callers);
  AddMlNdtResidualsQuaternion(layer,
                              points,
                              PaperObjectiveOptions(),
                              q.coeffs().data(),
                              t.data(),
                              &problem);
  EXPECT_EQ(problem.GetManifold(q.coeffs().data()), callers);
  // A second scan on the same pose blocks keeps it too.
  AddMlNdtResidualsQuaternion(layer,
                              points,
                              PaperObjectiveOptions(),
                              q.coeffs().data(),
                              t.data(),
                              &problem);
  EXPECT_EQ(problem.GetManifold(q.coeffs().data()), callers);
  EXPECT_EQ(problem.NumResidualBlocks(), 2 * static_cast<int>(points.size()));

  // And a manifold set by a first call is not replaced by a second one.
  ceres::Problem second;
  AddMlNdtResidualsQuaternion(layer,
                              points,
                              PaperObjectiveOptions(),
                              q.coeffs().data(),
                              t.data(),
                              &second);
  const ceres::Manifold* first = second.GetManifold(q.coeffs().data());
  ASSERT_NE(first, nullptr);
  AddMlNdtResidualsQuaternion(layer,
                              points,
                              PaperObjectiveOptions(),
                              q.coeffs().data(),
                              t.data(),
                              &second);
  EXPECT_EQ(second.GetManifold(q.coeffs().data()), first);
}

TEST(AddMlNdtResiduals, ProblemCostIsHalfTheScore) {
  const NdtLayer& layer = RoomGrid().layer(3);
  const std::vector<Vector3d> points = InputScan(20);
  Vector6d xi = TruePose();
  xi += (Vector6d() << 0.05, -0.04, 0.03, 0.01, -0.02, 0.015).finished();
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    for (const LossType loss :
         {LossType::NONE, LossType::HUBER, LossType::CAUCHY}) {
      SCOPED_TRACE(std::string(UnmatchedPolicyToString(policy)) + " " +
                   LossTypeToString(loss));
      const ScoreEvaluation score = EvaluateScore(
          layer, points, xi, testing::Objective(policy, loss, 2.0));
      ASSERT_GT(score.matched, points.size() / 2);
      if (policy == UnmatchedPolicy::ZERO_RESIDUAL) {
        EXPECT_GT(score.unmatched,
                  0u);  // So that the policy makes a difference.
      }
      ObjectiveOptions options = PaperObjectiveOptions();
      options.unmatched_policy = policy;

      // The 6-vector: cost and gradient.
      Vector6d xi_block = xi;
      ceres::Problem six;
      options.loss = loss;
      options.loss_scale = 2.0;
      AddMlNdtResiduals(layer, points, options, xi_block.data(), &six);
      double cost = kNaN;
      std::vector<double> gradient;
      ASSERT_TRUE(six.Evaluate(ceres::Problem::EvaluateOptions(),
                               &cost,
                               nullptr,
                               &gradient,
                               nullptr));
      EXPECT_NEAR(cost, 0.5 * score.score, 1e-10 * score.score);
      ASSERT_EQ(gradient.size(), 6u);
      EXPECT_TRUE(EigenNear(Eigen::Map<const Vector6d>(gradient.data()),
                            0.5 * score.gradient,
                            1e-9 * score.gradient.norm()));

      // The quaternion: cost.
      Eigen::Quaterniond q(EulerRotation(xi(3), xi(4), xi(5)));
      Vector3d t = xi.head<3>();
      ceres::Problem quaternion;
      options.loss = loss;
      options.loss_scale = 2.0;
      AddMlNdtResidualsQuaternion(
          layer, points, options, q.coeffs().data(), t.data(), &quaternion);
      EXPECT_NEAR(
          ProblemCost(&quaternion), 0.5 * score.score, 1e-9 * score.score);
    }
  }
}

// Solves layers 3 (0.87 m) and 4 (0.43 m) in turn, one Problem per layer;
// the cell association is redone inside every evaluation. (Starting on the
// coarser layers is not needed for a 0.3 m offset, and with hard cell
// assignment the 3.5 m and 1.7 m layers of this small room converge to poses
// several cm off.)
TEST(AddMlNdtResiduals, SolvingRecoversKnownTransform) {
  const LayeredGrid& grid = RoomGrid();
  ASSERT_EQ(grid.num_layers(), 4);
  const std::vector<Vector3d> points = InputScan(2);
  ASSERT_GT(points.size(), 2000u);
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    SCOPED_TRACE(UnmatchedPolicyToString(policy));
    Vector6d xi = Vector6d::Zero();
    ObjectiveOptions options = PaperObjectiveOptions();
    options.unmatched_policy = policy;
    for (int layer = 3; layer <= 4; ++layer) {
      ceres::Problem problem;
      AddMlNdtResiduals(
          grid.layer(layer), points, options, xi.data(), &problem);
      ceres::Solver::Summary summary;
      ceres::Solve(TightDenseQr(), &problem, &summary);
      ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
      EXPECT_LT(summary.final_cost, summary.initial_cost);
    }
    const Isometry3d truth = PoseVectorToIsometry(TruePose());
    const Isometry3d estimate = PoseVectorToIsometry(xi);
    EXPECT_LT(TranslationErrorM(estimate, truth), 0.01) << xi.transpose();
    EXPECT_LT(RotationErrorRad(estimate, truth), 0.1 * kDegToRad)
        << xi.transpose();
  }
}

// The same, in one Problem whose residuals are moved from layer 3 to layer 4
// by rebinding: same cost as fresh residuals on each layer, same result.
TEST(AddMlNdtResiduals, BoundResidualsMoveBetweenLayersWithoutNewBlocks) {
  const LayeredGrid& grid = RoomGrid();
  const std::vector<Vector3d> points = InputScan(2);
  Vector6d xi = Vector6d::Zero();
  LayerBinding binding(grid.layer(3));
  ceres::Problem problem;
  AddMlNdtResiduals(
      binding, points, PaperObjectiveOptions(), xi.data(), &problem);
  for (int layer = 3; layer <= 4; ++layer) {
    binding.Rebind(grid.layer(layer));
    Vector6d fresh_xi = xi;
    ceres::Problem fresh;
    AddMlNdtResiduals(grid.layer(layer),
                      points,
                      PaperObjectiveOptions(),
                      fresh_xi.data(),
                      &fresh);
    const double cost = ProblemCost(&problem);
    EXPECT_EQ(cost, ProblemCost(&fresh)) << "layer " << layer;
    ceres::Solver::Summary summary;
    ceres::Solve(TightDenseQr(), &problem, &summary);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
    EXPECT_LT(summary.final_cost, cost);
  }
  EXPECT_EQ(problem.NumResidualBlocks(), static_cast<int>(points.size()));
  const Isometry3d truth = PoseVectorToIsometry(TruePose());
  const Isometry3d estimate = PoseVectorToIsometry(xi);
  EXPECT_LT(TranslationErrorM(estimate, truth), 0.01) << xi.transpose();
  EXPECT_LT(RotationErrorRad(estimate, truth), 0.1 * kDegToRad)
      << xi.transpose();
}

TEST(AddMlNdtResidualsQuaternion, BoundResidualsFollowRebind) {
  const LayeredGrid& grid = RoomGrid();
  const std::vector<Vector3d> points = InputScan(10);
  Eigen::Quaterniond q(EulerRotation(0.01, -0.02, 0.03));
  Vector3d t(0.1, -0.1, 0.05);
  LayerBinding binding(grid.layer(2));
  ceres::Problem bound;
  AddMlNdtResidualsQuaternion(binding,
                              points,
                              PaperObjectiveOptions(),
                              q.coeffs().data(),
                              t.data(),
                              &bound);
  for (int layer = 2; layer <= 4; ++layer) {
    binding.Rebind(grid.layer(layer));
    ceres::Problem fixed;
    AddMlNdtResidualsQuaternion(grid.layer(layer),
                                points,
                                PaperObjectiveOptions(),
                                q.coeffs().data(),
                                t.data(),
                                &fixed);
    const double cost = ProblemCost(&bound);
    EXPECT_GT(cost, 0.0);
    EXPECT_EQ(cost, ProblemCost(&fixed)) << "layer " << layer;
  }
}

TEST(AddMlNdtResidualsQuaternion, SolvingRecoversKnownTransform) {
  const LayeredGrid& grid = RoomGrid();
  const std::vector<Vector3d> points = InputScan(2);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Vector3d t = Vector3d::Zero();
  ObjectiveOptions options = PaperObjectiveOptions();
  options.unmatched_policy = UnmatchedPolicy::NEAREST_CELL;
  for (int layer = 3; layer <= 4; ++layer) {
    ceres::Problem problem;
    AddMlNdtResidualsQuaternion(grid.layer(layer),
                                points,
                                options,
                                q.coeffs().data(),
                                t.data(),
                                &problem);
    ceres::Solver::Summary summary;
    ceres::Solve(TightDenseQr(), &problem, &summary);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
    EXPECT_LT(summary.final_cost, summary.initial_cost);
  }
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);  // Kept on the manifold.
  Isometry3d estimate = Isometry3d::Identity();
  estimate.linear() = q.toRotationMatrix();
  estimate.translation() = t;
  const Isometry3d truth = PoseVectorToIsometry(TruePose());
  EXPECT_LT(TranslationErrorM(estimate, truth), 0.01) << t.transpose();
  EXPECT_LT(RotationErrorRad(estimate, truth), 0.1 * kDegToRad);
}

TEST(AddMlNdtResiduals, CallersPriorSolvesJointly) {
  const NdtLayer& layer = RoomGrid().layer(4);
  const std::vector<Vector3d> points = InputScan(2);
  const Vector6d truth = TruePose();
  // A prior pulling the translation 5 cm away from the truth, with a weight
  // equal to the ML-NDT stiffness along the offset (Hessian of the cost
  // 0.5 * score, rotation eliminated by a Schur complement): the joint
  // optimum lies about half-way.
  const Vector3d t0 = truth.head<3>() + Vector3d(0.04, -0.03, 0.0);
  const Vector3d offset = t0 - truth.head<3>();
  const Matrix6d h =
      EvaluateScore(layer,
                    points,
                    truth,
                    testing::Objective(
                        UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0))
          .hessian;
  const Matrix3d stiffness =
      0.5 * (h.topLeftCorner<3, 3>() -
             h.topRightCorner<3, 3>() * h.bottomRightCorner<3, 3>().inverse() *
                 h.bottomLeftCorner<3, 3>());
  const double weight = offset.dot(stiffness * offset) / offset.squaredNorm();
  ASSERT_GT(weight, 0.0);

  Vector6d xi = truth;
  ceres::Problem problem;
  AddMlNdtResiduals(
      layer, points, PaperObjectiveOptions(), xi.data(), &problem);
  problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<TranslationPrior, 3, 6>(
          new TranslationPrior(t0, std::sqrt(weight))),
      nullptr,
      xi.data());
  EXPECT_EQ(problem.NumResidualBlocks(), static_cast<int>(points.size()) + 1);
  ceres::Solver::Summary summary;
  ceres::Solve(TightDenseQr(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();

  // Pulled part of the way from the truth (near the ML-NDT optimum) towards
  // t0: s is the fraction of the offset covered.
  const double s =
      (xi.head<3>() - truth.head<3>()).dot(offset) / offset.squaredNorm();
  // The quadratic model's prediction (K + w I)^-1 w d; the true cost is only
  // piecewise quadratic, hence the loose tolerance.
  const double predicted =
      offset.dot((stiffness + weight * Matrix3d::Identity()).inverse() *
                 (weight * offset)) /
      offset.squaredNorm();
  EXPECT_NEAR(s, predicted, 0.2) << xi.transpose();
  EXPECT_GT(s, 0.15) << xi.transpose();
  EXPECT_LT(s, 0.85) << xi.transpose();
  EXPECT_LT((xi.head<3>() - truth.head<3>() - s * offset).norm(), 0.01)
      << xi.transpose();

  // The joint cost is lower there than at either term's own optimum.
  const double joint = summary.final_cost;
  EXPECT_NEAR(ProblemCost(&problem), joint, 1e-9 * joint);
  const Vector6d solution = xi;
  xi = truth;
  const double at_truth = ProblemCost(&problem);
  xi.head<3>() = t0;
  const double at_prior = ProblemCost(&problem);
  xi = solution;
  EXPECT_LT(joint, at_truth);
  EXPECT_LT(joint, at_prior);
  // At the truth the prior term alone is 0.5 * weight * |offset|^2.
  const double ndt_at_truth =
      0.5 *
      EvaluateScore(layer,
                    points,
                    truth,
                    testing::Objective(
                        UnmatchedPolicy::ZERO_RESIDUAL, LossType::NONE, 1.0))
          .score;
  EXPECT_NEAR(at_truth - ndt_at_truth,
              0.5 * weight * offset.squaredNorm(),
              1e-9 * at_truth);
}

}  // namespace
}  // namespace mlndt
