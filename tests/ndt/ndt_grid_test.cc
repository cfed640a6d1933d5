#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mlndt/grid/layered_grid.h"
#include "mlndt/ndt/ndt_registration.h"

namespace mlndt {
namespace {

// Points spread over a box, seeded, plus both corners.
PointCloud BoxCloud(const Eigen::Vector3d& min,
                    const Eigen::Vector3d& max,
                    int n,
                    int seed) {
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

// The conventional NDT grid of `cloud`: NdtGridOptions, then a one-layer
// LayeredGrid (its layer 1 into *grid, its facts into *info).
bool BuildNdtGrid(const NdtOptions& options,
                  const PointCloud& cloud,
                  NdtLayer* grid,
                  LayerInfo* info,
                  std::string* error) {
  LayeredGridOptions grid_options;
  LayeredGrid map;
  if (!NdtGridOptions(options, cloud, &grid_options, error) ||
      !LayeredGrid::Build(grid_options, cloud, &map, error)) {
    return false;
  }
  if (map.num_layers() != 1) {
    *error = "not one layer";
    return false;
  }
  *grid = map.layer(1);
  *info = map.layer_info()[0];
  return true;
}

TEST(NdtGrid, DefaultCellIsThePapersLayerTwoCell) {
  // Section 4's example box, 100 x 100 x 20 m: layer 2 of q = 8 has 14.62 m
  // cells in a 7 x 7 x 2 grid; (V / 64)^(1/3) is the same edge.
  const PointCloud cloud = BoxCloud(
      Eigen::Vector3d(-50, -50, 0), Eigen::Vector3d(50, 50, 20), 20000, 1);
  NdtLayer grid;
  LayerInfo info;
  std::string error;
  ASSERT_TRUE(BuildNdtGrid(NdtOptions(), cloud, &grid, &info, &error)) << error;
  EXPECT_NEAR(grid.cell_size(), std::cbrt(100.0 * 100.0 * 20.0 / 64.0), 1e-9);
  EXPECT_NEAR(grid.cell_size(), 14.62, 0.005);
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(7, 7, 2));
  LayeredGrid map;
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &map, &error))
      << error;
  EXPECT_NEAR(grid.cell_size(), map.layer(2).cell_size(), 1e-9);
  EXPECT_EQ(grid.dims(), map.layer(2).dims());
  EXPECT_EQ(grid.cells().size(), map.layer(2).cells().size());
  EXPECT_EQ(info.layer, 1);
  EXPECT_EQ(info.cell_size_m, grid.cell_size());
  EXPECT_EQ(info.occupied_cells, grid.cells().size());
}

TEST(NdtGrid, GivenCellSizeAndDims) {
  const PointCloud cloud = BoxCloud(
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10.5, 6.0, 3.2), 20000, 2);
  NdtOptions options;
  options.cell_size_m = 1.0;
  NdtLayer grid;
  LayerInfo info;
  std::string error;
  ASSERT_TRUE(BuildNdtGrid(options, cloud, &grid, &info, &error)) << error;
  EXPECT_EQ(grid.cell_size(), 1.0);
  // floor(extent / k) + 1 cells per axis, as the layers of the ML-NDT map.
  EXPECT_EQ(grid.dims(), Eigen::Vector3i(11, 7, 4));
  EXPECT_EQ(info.dims, grid.dims());
  EXPECT_EQ(info.cell_size_m, 1.0);
  EXPECT_EQ(grid.origin(), Eigen::Vector3d::Zero());
}

TEST(NdtGrid, CellsMatchDirectComputation) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(8, 6, 4), 5000, 3);
  NdtOptions options;
  options.cell_size_m = 2.0;
  options.regularization.min_eigenvalue_m2 = 0.0;
  NdtLayer grid;
  LayerInfo info;
  std::string error;
  ASSERT_TRUE(BuildNdtGrid(options, cloud, &grid, &info, &error)) << error;
  // Cell (1, 2, 0): points with x in [2, 4), y in [4, 6), z in [0, 2).
  std::vector<Eigen::Vector3d> inside;
  for (const Eigen::Vector3d& p : cloud.points()) {
    if (p.x() >= 2 && p.x() < 4 && p.y() >= 4 && p.y() < 6 && p.z() < 2)
      inside.push_back(p);
  }
  ASSERT_GE(inside.size(), 5u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : inside) mean += p;
  mean /= static_cast<double>(inside.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : inside)
    covariance += (p - mean) * (p - mean).transpose();
  covariance /= static_cast<double>(inside.size() - 1);  // Eq. (3), unbiased.
  const NdtCell* cell = grid.CellAt(Eigen::Vector3i(1, 2, 0));
  ASSERT_NE(cell, nullptr);
  EXPECT_EQ(cell->count, static_cast<int32_t>(inside.size()));
  EXPECT_LT((cell->mean - mean).norm(), 1e-9);
  // A box-filling cell is well conditioned: no eigenvalue is raised.
  EXPECT_LT((cell->covariance - covariance).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((cell->information * cell->covariance - Eigen::Matrix3d::Identity())
                .norm(),
            1e-9);
}

TEST(NdtGrid, SparseCellsAreCounted) {
  PointCloud cloud = BoxCloud(
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.9, 1.9, 1.9), 100, 4);
  for (int i = 0; i < 3; ++i)
    cloud.Add(Eigen::Vector3d(5.5 + 0.1 * i, 0.5, 0.5 + 0.2 * i));
  NdtOptions options;
  options.cell_size_m = 2.0;
  options.min_points_per_cell = 5;
  NdtLayer grid;
  LayerInfo info;
  std::string error;
  ASSERT_TRUE(BuildNdtGrid(options, cloud, &grid, &info, &error)) << error;
  EXPECT_EQ(info.occupied_cells, 1u);
  EXPECT_EQ(info.sparse_cells, 1u);
  EXPECT_EQ(grid.cells().size(), 1u);
  EXPECT_EQ(grid.Lookup(Eigen::Vector3d(5.6, 0.5, 0.5)), nullptr);
  EXPECT_NE(grid.Lookup(Eigen::Vector3d(1.0, 1.0, 1.0)), nullptr);
}

TEST(NdtGrid, BadInputFailsWithAMessage) {
  NdtLayer grid;
  LayerInfo info;
  std::string error;
  EXPECT_FALSE(BuildNdtGrid(NdtOptions(), PointCloud(), &grid, &info, &error));
  EXPECT_NE(error.find("empty"), std::string::npos) << error;

  PointCloud nan_cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 10, 5);
  nan_cloud.Add(
      Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  EXPECT_FALSE(BuildNdtGrid(NdtOptions(), nan_cloud, &grid, &info, &error));
  EXPECT_NE(error.find("non-finite"), std::string::npos) << error;

  PointCloud same;
  for (int i = 0; i < 10; ++i) same.Add(Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(BuildNdtGrid(NdtOptions(), same, &grid, &info, &error));
  EXPECT_NE(error.find("coincide"), std::string::npos) << error;

  const PointCloud big =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e4, 1e4, 1e4), 10, 6);
  NdtOptions tiny;
  tiny.cell_size_m = 1e-3;
  EXPECT_FALSE(BuildNdtGrid(tiny, big, &grid, &info, &error));
  EXPECT_NE(error.find("too many cells"), std::string::npos) << error;

  NdtOptions invalid;
  invalid.cell_size_m = -1.0;
  EXPECT_FALSE(invalid.IsValid(&error));
  EXPECT_NE(error.find("cell_size_m"), std::string::npos) << error;
  invalid = NdtOptions();
  invalid.min_points_per_cell = 3;
  EXPECT_FALSE(invalid.IsValid(&error));
}

}  // namespace
}  // namespace mlndt
