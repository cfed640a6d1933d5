#include "mlndt/grid/layered_grid.h"

#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

namespace mlndt {
namespace {

// Points spread over a box, seeded.
PointCloud BoxCloud(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int n, int seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointCloud cloud;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p(a) = min(a) + (max(a) - min(a)) * u(rng);
    cloud.Add(p);
  }
  cloud.Add(min);
  cloud.Add(max);
  return cloud;
}

TEST(LayeredGrid, PaperWorkedExampleLayerTwo) {
  // Section 4: 100 x 100 x 20 m, q = 8, layer 2 -> 14.62 m cells, 7 x 7 x 2.
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(-50, -50, 0), Eigen::Vector3d(50, 50, 20), 20000, 1);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), cloud, &grid, &error)) << error;
  ASSERT_EQ(grid.num_layers(), 4);
  EXPECT_NEAR(grid.layer(2).cell_size(), 14.62, 0.005);
  EXPECT_EQ(grid.layer(2).dims(), Eigen::Vector3i(7, 7, 2));
  EXPECT_NEAR(grid.layer(1).cell_size(), 29.24, 0.01);
  EXPECT_NEAR(grid.layer(4).cell_size(), 3.655, 0.005);
}

TEST(LayeredGrid, CellSizesHalveForQEight) {
  const std::vector<double> sizes =
      LayerCellSizes(LayeredGridOptions(), Eigen::Vector3d(100, 100, 20));
  ASSERT_EQ(sizes.size(), 4u);
  for (size_t i = 1; i < sizes.size(); ++i) EXPECT_NEAR(sizes[i - 1] / sizes[i], 2.0, 1e-12);
}

TEST(LayeredGrid, FinestCellSizeDerivesLayerCount) {
  LayeredGridOptions options;
  options.finest_cell_size_m = 1.0;
  const std::vector<double> sizes = LayerCellSizes(options, Eigen::Vector3d(160, 160, 20));
  ASSERT_FALSE(sizes.empty());
  EXPECT_LE(sizes.back(), 1.0);
  EXPECT_GT(sizes.back(), 0.5);  // Smallest n that reaches 1 m, not more.
}

TEST(LayeredGrid, MomentsMatchDirectComputation) {
  // Aggregated coarse cells must equal cells computed from the points.
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 30, 10), 30000, 2);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), cloud, &grid, &error)) << error;
  for (int layer = 1; layer <= grid.num_layers(); ++layer) {
    const NdtLayer& l = grid.layer(layer);
    // Direct: collect points of the cell containing a probe point.
    const Eigen::Vector3d probe(13.3, 17.1, 4.2);
    const Eigen::Vector3i ijk = l.CellCoordinates(probe);
    std::vector<Eigen::Vector3d> inside;
    for (const auto& p : cloud.points()) {
      if (l.CellCoordinates(p) == ijk) inside.push_back(p);
    }
    const NdtCell* cell = l.Lookup(probe);
    ASSERT_NE(cell, nullptr) << "layer " << layer;
    ASSERT_EQ(cell->count, static_cast<int>(inside.size())) << "layer " << layer;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : inside) mean += p;
    mean /= inside.size();
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : inside) cov += (p - mean) * (p - mean).transpose();
    cov /= (inside.size() - 1.0);  // Eq. (3), unbiased.
    EXPECT_TRUE(cell->mean.isApprox(mean, 1e-9)) << "layer " << layer;
    // Uniform points in a cube: well-conditioned, no regularisation.
    EXPECT_TRUE(cell->covariance.isApprox(cov, 1e-7)) << "layer " << layer;
  }
}

TEST(LayeredGrid, NonCubicDivisionConstantBinsEveryLayer) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 40, 10), 20000, 3);
  LayeredGridOptions options;
  options.division_constant = 10;
  options.num_layers = 3;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  const double volume = 40.0 * 40.0 * 10.0;
  for (int i = 1; i <= 3; ++i) {
    EXPECT_NEAR(grid.layer(i).cell_size(), std::cbrt(volume / std::pow(10.0, i)), 1e-9);
    size_t total = 0;
    for (const NdtCell& c : grid.layer(i).cells()) total += c.count;
    EXPECT_LE(total, cloud.size());
    EXPECT_GT(total, cloud.size() * 9 / 10);
  }
}

TEST(LayeredGrid, LookupIsConsistentWithCellBounds) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(-10, -10, -2), Eigen::Vector3d(10, 10, 2), 20000, 4);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), cloud, &grid, &error)) << error;
  const NdtLayer& layer = grid.layer(3);
  for (const auto& p : cloud.points()) {
    const NdtCell* cell = layer.Lookup(p);
    if (cell == nullptr) continue;
    // The cell's mean lies in the same cell as the point (cells are convex).
    EXPECT_EQ(layer.CellCoordinates(cell->mean), layer.CellCoordinates(p));
  }
  EXPECT_EQ(layer.Lookup(Eigen::Vector3d(1e9, 0, 0)), nullptr);
  EXPECT_EQ(layer.Lookup(Eigen::Vector3d(std::nan(""), 0, 0)), nullptr);
}

TEST(LayeredGrid, FarFromOriginMatchesCentred) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(30, 30, 6), 20000, 5);
  const Eigen::Vector3d offset(4.0e6, 5.0e6, 100.0);
  std::vector<Eigen::Vector3d> moved;
  for (const auto& p : cloud.points()) moved.push_back(p + offset);
  LayeredGrid near, far;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), cloud, &near, &error)) << error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), PointCloud(moved), &far, &error)) << error;
  for (int i = 1; i <= near.num_layers(); ++i) {
    ASSERT_EQ(near.layer(i).cells().size(), far.layer(i).cells().size());
    for (size_t c = 0; c < near.layer(i).cells().size(); ++c) {
      const NdtCell& a = near.layer(i).cells()[c];
      const NdtCell& b = far.layer(i).cells()[c];
      EXPECT_EQ(a.count, b.count);
      EXPECT_LT((a.mean + offset - b.mean).norm(), 1e-6);
      EXPECT_LT((a.covariance - b.covariance).norm(), 1e-6 * a.covariance.norm());
    }
  }
}

TEST(LayeredGrid, MinPointsPerCellIsRespected) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(50, 50, 10), 3000, 6);
  LayeredGridOptions options;
  options.min_points_per_cell = 20;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  for (int i = 1; i <= grid.num_layers(); ++i) {
    for (const NdtCell& c : grid.layer(i).cells()) EXPECT_GE(c.count, 20);
  }
  EXPECT_GT(grid.layer_info().back().sparse_cells, 0u);
}

TEST(LayeredGrid, RejectsBadInput) {
  LayeredGrid grid;
  std::string error;
  EXPECT_FALSE(LayeredGrid::Build(LayeredGridOptions(), PointCloud(), &grid, &error));
  EXPECT_NE(error.find("empty"), std::string::npos);
  PointCloud with_nan = BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 100, 7);
  with_nan.Add(Eigen::Vector3d(std::nan(""), 0, 0));
  EXPECT_FALSE(LayeredGrid::Build(LayeredGridOptions(), with_nan, &grid, &error));
  EXPECT_NE(error.find("non-finite"), std::string::npos);
  PointCloud same(std::vector<Eigen::Vector3d>(10, Eigen::Vector3d(1, 2, 3)));
  EXPECT_FALSE(LayeredGrid::Build(LayeredGridOptions(), same, &grid, &error));
  EXPECT_NE(error.find("coincide"), std::string::npos);
  EXPECT_TRUE(grid.empty());  // No partial state.
}

TEST(LayeredGrid, InvalidOptionsNameTheField) {
  const PointCloud cloud = BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(9, 9, 9), 500, 8);
  LayeredGrid grid;
  std::string error;
  LayeredGridOptions options;
  options.division_constant = 1;
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("division_constant"), std::string::npos);
  options = LayeredGridOptions();
  options.regularization.min_eigenvalue_ratio = std::nan("");
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("min_eigenvalue_ratio"), std::string::npos);
  options = LayeredGridOptions();
  options.finest_cell_size_m = 1e-4;
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("max_num_layers"), std::string::npos);
}

TEST(LayeredGrid, FlatCloudStillBuilds) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 20.0);
  PointCloud plane;
  for (int i = 0; i < 5000; ++i) plane.Add(Eigen::Vector3d(u(rng), u(rng), 0.0));
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(LayeredGridOptions(), plane, &grid, &error)) << error;
  ASSERT_FALSE(grid.layer(2).cells().empty());
  // A planar cell is regularised: smallest eigenvalue = largest / 100.
  const NdtCell& cell = grid.layer(2).cells().front();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cell.covariance);
  EXPECT_NEAR(es.eigenvalues()(0), es.eigenvalues()(2) / 100.0, 1e-9 * es.eigenvalues()(2));
}

}  // namespace
}  // namespace mlndt
