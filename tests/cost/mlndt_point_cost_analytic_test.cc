// MlNdtPointCostAnalytic (mlndt_point_cost_analytic.h) against the auto-diff
// MlNdtPointCost on the bundled KITTI pair 0 -> 1: same residuals and
// Jacobians for every sample, at a pose off the solution.

#include "mlndt/cost/mlndt_point_cost_analytic.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

TEST(MlNdtPointCostAnalytic, EqualsAutoDiffOnRealScans) {
  PointCloud scan0, scan1, samples;
  std::string error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000000.pcd"),
                             &scan0,
                             nullptr,
                             &error))
      << error;
  ASSERT_TRUE(ReadPointCloud(testing::BundledDataPath("kitti/pcd/000001.pcd"),
                             &scan1,
                             nullptr,
                             &error))
      << error;
  LayeredGrid map;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), scan0, &map, &error))
      << error;
  ASSERT_TRUE(SamplePoints(SamplingOptions(), scan1, &samples, nullptr, &error))
      << error;
  // Near the reference (0.69 m forward), tilted so every angle matters.
  const Vector6d xi = PoseVectorFromDegrees(0.8, 0.05, -0.02, 1.5, -2.0, 3.0);
  const double* parameters[] = {xi.data()};
  int matched = 0;
  for (const UnmatchedPolicy policy :
       {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
    for (const Eigen::Vector3d& p : samples.points()) {
      std::unique_ptr<ceres::CostFunction> autodiff(
          MlNdtPointCost::Create(map.layer(map.num_layers()), p, policy));
      const MlNdtPointCostAnalytic analytic(
          map.layer(map.num_layers()), p, policy);
      Eigen::Vector3d r_a, r_b;
      Eigen::Matrix<double, 3, 6, Eigen::RowMajor> j_a, j_b;
      double* ja[] = {j_a.data()};
      double* jb[] = {j_b.data()};
      ASSERT_TRUE(autodiff->Evaluate(parameters, r_a.data(), ja));
      ASSERT_TRUE(analytic.Evaluate(parameters, r_b.data(), jb));
      ASSERT_LT((r_a - r_b).norm(), 1e-9 * (1.0 + r_a.norm()));
      ASSERT_LT((j_a - j_b).norm(), 1e-9 * (1.0 + j_a.norm()));
      matched += j_a.norm() > 0.0;
    }
  }
  // Most samples are matched: the comparison is not between zeros.
  EXPECT_GT(matched, static_cast<int>(samples.size()));
}

}  // namespace
}  // namespace mlndt
