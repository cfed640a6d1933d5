// Tests of MlNdtPairFactor (mlndt_pair_factor.h): on the bundled KITTI pair
// 0 -> 1 it gives the cost, gradient and Gauss-Newton matrix J^T J of the
// per-point pair blocks it replaces, for every loss, and the same solution.

#include "mlndt/cost/mlndt_pair_factor.h"

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/add_pair_residuals.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

struct KittiPair {
  LayeredGrid map;                       // Of scan 0.
  std::vector<Eigen::Vector3d> samples;  // Of scan 1.
};

const KittiPair& Pair() {
  static const KittiPair* pair = [] {
    auto* p = new KittiPair;
    PointCloud scan0, scan1, sampled;
    std::string error;
    EXPECT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000000.pcd"),
                               &scan0,
                               nullptr,
                               &error))
        << error;
    EXPECT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000001.pcd"),
                               &scan1,
                               nullptr,
                               &error))
        << error;
    EXPECT_TRUE(
        LayeredGrid::Build(LayeredGridOptions(),
                           FilterByRange(RangeFilterOptions(), scan0, nullptr),
                           &p->map,
                           &error))
        << error;
    EXPECT_TRUE(
        SamplePoints(SamplingOptions(),
                     FilterByRange(RangeFilterOptions(), scan1, nullptr),
                     &sampled,
                     nullptr,
                     &error))
        << error;
    p->samples = sampled.points();
    return p;
  }();
  return *pair;
}

// Pose 0 at a world pose, pose 1 0.3 m / 2 deg from the reference
// (reference_pairs.json "0_1": 0.69 m forward).
struct Poses {
  double q0[4], t0[3] = {4.0, -2.0, 0.5}, q1[4], t1[3];
  Poses() {
    const Eigen::Quaterniond r0(
        Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
    const Eigen::Quaterniond r1 =
        r0 * Eigen::Quaterniond(Eigen::AngleAxisd(
                 2.0 * kDegToRad, Eigen::Vector3d(0.1, 0.2, 1.0).normalized()));
    Eigen::Map<Eigen::Quaterniond> m0(q0);
    m0 = r0;
    Eigen::Map<Eigen::Quaterniond> m1(q1);
    m1 = r1;
    Eigen::Map<Eigen::Vector3d> m_t1(t1);
    m_t1 =
        Eigen::Map<Eigen::Vector3d>(t0) + r0 * Eigen::Vector3d(0.99, 0.1, -0.1);
  }
};

struct Evaluation {
  double cost = 0.0;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd gauss_newton;  // J^T J in the tangent spaces.
  int blocks = 0;
};

Evaluation Evaluate(const PairResidualOptions& options, Poses poses) {
  ceres::Problem problem;
  const LayeredGrid& map = Pair().map;
  Evaluation e;
  e.blocks = static_cast<int>(AddMlNdtPairResiduals(map.layer(map.num_layers()),
                                                    Pair().samples,
                                                    options,
                                                    poses.q0,
                                                    poses.t0,
                                                    poses.q1,
                                                    poses.t1,
                                                    &problem)
                                  .size());
  std::vector<double> gradient;
  ceres::CRSMatrix crs;
  EXPECT_TRUE(problem.Evaluate(
      ceres::Problem::EvaluateOptions(), &e.cost, nullptr, &gradient, &crs));
  e.gradient = Eigen::Map<Eigen::VectorXd>(gradient.data(), gradient.size());
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row) {
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k)
      j(row, crs.cols[k]) = crs.values[k];
  }
  e.gauss_newton = j.transpose() * j;
  return e;
}

class PairFactorVsPointBlocks : public ::testing::TestWithParam<LossType> {};

TEST_P(PairFactorVsPointBlocks, SameCostGradientAndGaussNewtonMatrix) {
  PairResidualOptions points;
  points.objective.loss = GetParam();
  points.information_scale = 0.05;
  PairResidualOptions one_block = points;
  one_block.one_block_per_pair = true;
  const Evaluation expected = Evaluate(points, Poses());
  const Evaluation actual = Evaluate(one_block, Poses());
  ASSERT_GT(expected.blocks, 10000);
  EXPECT_EQ(actual.blocks, 1);
  EXPECT_GT(expected.cost, 1.0);
  EXPECT_NEAR(actual.cost, expected.cost, 1e-9 * expected.cost);
  ASSERT_EQ(actual.gradient.size(), 12);
  EXPECT_GT(expected.gradient.norm(), 1.0);
  EXPECT_LT((actual.gradient - expected.gradient).norm(),
            1e-8 * expected.gradient.norm());
  EXPECT_LT((actual.gauss_newton - expected.gauss_newton).norm(),
            1e-8 * expected.gauss_newton.norm());
}

INSTANTIATE_TEST_SUITE_P(Losses,
                         PairFactorVsPointBlocks,
                         ::testing::Values(LossType::NONE,
                                           LossType::HUBER,
                                           LossType::CAUCHY));

TEST(PairResidualOptions, InformationScaleScalesCostGradientAndInformation) {
  for (const bool one_block : {false, true}) {
    SCOPED_TRACE(one_block ? "one block" : "per point");
    PairResidualOptions unit;
    unit.one_block_per_pair = one_block;
    unit.information_scale = 1.0;
    PairResidualOptions weighted = unit;
    weighted.information_scale = 0.055;
    const Evaluation a = Evaluate(unit, Poses());
    const Evaluation b = Evaluate(weighted, Poses());
    EXPECT_NEAR(b.cost, 0.055 * a.cost, 1e-9 * a.cost);
    EXPECT_LT((b.gradient - 0.055 * a.gradient).norm(),
              1e-8 * a.gradient.norm());
    EXPECT_LT((b.gauss_newton - 0.055 * a.gauss_newton).norm(),
              1e-8 * a.gauss_newton.norm());
  }
  // The default is the calibrated scale; bad scales are refused by name.
  EXPECT_EQ(PairResidualOptions().information_scale,
            kCalibratedPairInformationScale);
  std::string error;
  PairResidualOptions bad;
  bad.information_scale = 0.0;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("information_scale"), std::string::npos) << error;
  bad.information_scale = 1.0;
  bad.objective.loss_scale = -1.0;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("objective: "), std::string::npos) << error;
}

// The weighted pair's covariance (ceres::Covariance of the one-block
// problem, mapped to the pose vector xi) is Register's covariance for the
// same pair divided by w: what docs/embedding.md calibrates w on.
TEST(MlNdtPairFactor, CovarianceIsRegistersOverTheInformationScale) {
  PointCloud scan1;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000001.pcd"),
                             &scan1,
                             nullptr,
                             &error))
      << error;
  RegistrationSummary summary;
  Register(RegistrationOptions(),
           Pair().map,
           scan1,
           Isometry3d::Identity(),
           &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.message;
  double q0[4] = {0, 0, 0, 1}, t0[3] = {0, 0, 0}, q1[4], t1[3];
  const Eigen::Quaterniond rotation(summary.reference_from_input.linear());
  for (int k = 0; k < 4; ++k) q1[k] = rotation.coeffs()[k];
  for (int k = 0; k < 3; ++k)
    t1[k] = summary.reference_from_input.translation()[k];
  PairResidualOptions options;
  options.one_block_per_pair = true;
  ceres::Problem problem;
  const LayeredGrid& map = Pair().map;
  AddMlNdtPairResiduals(map.layer(map.num_layers()),
                        Pair().samples,
                        options,
                        q0,
                        t0,
                        q1,
                        t1,
                        &problem);
  problem.SetParameterBlockConstant(q0);
  problem.SetParameterBlockConstant(t0);
  ceres::Covariance covariance{ceres::Covariance::Options()};
  ASSERT_TRUE(covariance.Compute({{q1, q1}, {q1, t1}, {t1, t1}}, &problem));
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> tangent;
  ASSERT_TRUE(
      covariance.GetCovarianceMatrixInTangentSpace({q1, t1}, tangent.data()));
  // d xi / d (rotation tangent, translation), central differences through
  // the quaternion manifold's Plus.
  const ceres::EigenQuaternionManifold manifold;
  const auto xi_at = [&](const Vector6d& delta) {
    double q[4];
    manifold.Plus(q1, delta.data(), q);
    Isometry3d pose = Isometry3d::Identity();
    pose.linear() = Eigen::Map<Eigen::Quaterniond>(q).toRotationMatrix();
    pose.translation() = Eigen::Map<Eigen::Vector3d>(t1) + delta.tail<3>();
    return IsometryToPoseVector(pose);
  };
  Matrix6d jacobian;
  for (int c = 0; c < 6; ++c) {
    Vector6d h = Vector6d::Zero();
    h(c) = 1e-6;
    jacobian.col(c) = (xi_at(h) - xi_at(-h)) / 2e-6;
  }
  const Matrix6d pair_covariance =
      jacobian * Matrix6d(tangent) * jacobian.transpose();
  const Matrix6d expected = summary.covariance / options.information_scale;
  EXPECT_LT((pair_covariance - expected).norm(), 1e-3 * expected.norm())
      << "pair:\n"
      << pair_covariance << "\nRegister / w:\n"
      << expected;
}

TEST(MlNdtPairFactor, SolvesToThePointBlocksSolution) {
  Poses start;
  Isometry3d solutions[2];
  for (const bool one_block : {false, true}) {
    Poses poses = start;
    PairResidualOptions options;
    options.one_block_per_pair = one_block;
    ceres::Problem problem;
    const LayeredGrid& map = Pair().map;
    AddMlNdtPairResiduals(map.layer(map.num_layers()),
                          Pair().samples,
                          options,
                          poses.q0,
                          poses.t0,
                          poses.q1,
                          poses.t1,
                          &problem);
    problem.SetParameterBlockConstant(poses.q0);
    problem.SetParameterBlockConstant(poses.t0);
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.function_tolerance = 1e-12;
    solver.parameter_tolerance = 1e-12;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
    Isometry3d w0 = Isometry3d::Identity(), w1 = Isometry3d::Identity();
    w0.linear() = Eigen::Map<Eigen::Quaterniond>(poses.q0).toRotationMatrix();
    w0.translation() = Eigen::Map<Eigen::Vector3d>(poses.t0);
    w1.linear() = Eigen::Map<Eigen::Quaterniond>(poses.q1)
                      .normalized()
                      .toRotationMatrix();
    w1.translation() = Eigen::Map<Eigen::Vector3d>(poses.t1);
    solutions[one_block] = w0.inverse() * w1;
  }
  EXPECT_LT(TranslationErrorM(solutions[0], solutions[1]), 1e-5);
  EXPECT_LT(RotationErrorRad(solutions[0], solutions[1]), 1e-6);
  // And it moved: 0.3 m from where it started.
  EXPECT_GT(solutions[1].translation().x(), 0.6);
}

}  // namespace
}  // namespace mlndt
