#include "mlndt/grid/layered_grid.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <random>

#include "mlndt/cloud/io.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// Points spread over a box, seeded.
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

TEST(LayeredGrid, PaperWorkedExampleLayerTwo) {
  // Section 4: 100 x 100 x 20 m, q = 8, layer 2 -> 14.62 m cells, 7 x 7 x 2.
  const PointCloud cloud = BoxCloud(
      Eigen::Vector3d(-50, -50, 0), Eigen::Vector3d(50, 50, 20), 20000, 1);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &grid, &error))
      << error;
  ASSERT_EQ(grid.num_layers(), 4);
  EXPECT_NEAR(grid.layer(2).cell_size(), 14.62, 0.005);
  EXPECT_EQ(grid.layer(2).dims(), Eigen::Vector3i(7, 7, 2));
  EXPECT_NEAR(grid.layer(1).cell_size(), 29.24, 0.01);
  EXPECT_NEAR(grid.layer(4).cell_size(), 3.655, 0.005);
}

TEST(LayeredGrid, CellSizesHalveForQEight) {
  const std::vector<double> sizes =
      LayerCellSizes(PaperLayeredGridOptions(), Eigen::Vector3d(100, 100, 20));
  ASSERT_EQ(sizes.size(), 4u);
  for (size_t i = 1; i < sizes.size(); ++i)
    EXPECT_NEAR(sizes[i - 1] / sizes[i], 2.0, 1e-12);
}

TEST(LayeredGrid, FinestCellSizeDerivesLayerCount) {
  LayeredGridOptions options;
  options.finest_cell_size_m = 1.0;
  const std::vector<double> sizes =
      LayerCellSizes(options, Eigen::Vector3d(160, 160, 20));
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
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &grid, &error))
      << error;
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
    ASSERT_EQ(cell->count, static_cast<int>(inside.size()))
        << "layer " << layer;
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
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.division_constant = 10;
  options.num_layers = 3;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  const double volume = 40.0 * 40.0 * 10.0;
  for (int i = 1; i <= 3; ++i) {
    EXPECT_NEAR(
        grid.layer(i).cell_size(), std::cbrt(volume / std::pow(10.0, i)), 1e-9);
    size_t total = 0;
    for (const NdtCell& c : grid.layer(i).cells()) total += c.count;
    EXPECT_LE(total, cloud.size());
    EXPECT_GT(total, cloud.size() * 9 / 10);
  }
}

TEST(LayeredGrid, LookupIsConsistentWithCellBounds) {
  const PointCloud cloud = BoxCloud(
      Eigen::Vector3d(-10, -10, -2), Eigen::Vector3d(10, 10, 2), 20000, 4);
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &grid, &error))
      << error;
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
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), cloud, &near, &error))
      << error;
  ASSERT_TRUE(LayeredGrid::Build(
      PaperLayeredGridOptions(), PointCloud(moved), &far, &error))
      << error;
  for (int i = 1; i <= near.num_layers(); ++i) {
    ASSERT_EQ(near.layer(i).cells().size(), far.layer(i).cells().size());
    for (size_t c = 0; c < near.layer(i).cells().size(); ++c) {
      const NdtCell& a = near.layer(i).cells()[c];
      const NdtCell& b = far.layer(i).cells()[c];
      EXPECT_EQ(a.count, b.count);
      EXPECT_LT((a.mean + offset - b.mean).norm(), 1e-6);
      EXPECT_LT((a.covariance - b.covariance).norm(),
                1e-6 * a.covariance.norm());
    }
  }
}

TEST(LayeredGrid, MinPointsPerCellIsRespected) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(50, 50, 10), 3000, 6);
  LayeredGridOptions options = PaperLayeredGridOptions();
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
  EXPECT_FALSE(LayeredGrid::Build(
      PaperLayeredGridOptions(), PointCloud(), &grid, &error));
  EXPECT_NE(error.find("empty"), std::string::npos);
  PointCloud with_nan =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 100, 7);
  with_nan.Add(Eigen::Vector3d(std::nan(""), 0, 0));
  EXPECT_FALSE(
      LayeredGrid::Build(PaperLayeredGridOptions(), with_nan, &grid, &error));
  EXPECT_NE(error.find("non-finite"), std::string::npos);
  PointCloud same(std::vector<Eigen::Vector3d>(10, Eigen::Vector3d(1, 2, 3)));
  EXPECT_FALSE(
      LayeredGrid::Build(PaperLayeredGridOptions(), same, &grid, &error));
  EXPECT_NE(error.find("coincide"), std::string::npos);
  EXPECT_TRUE(grid.empty());  // No partial state.
}

TEST(LayeredGrid, InvalidOptionsNameTheField) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(9, 9, 9), 500, 8);
  LayeredGrid grid;
  std::string error;
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.division_constant = 1;
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("division_constant"), std::string::npos);
  options = PaperLayeredGridOptions();
  options.regularization.min_eigenvalue_ratio = std::nan("");
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("min_eigenvalue_ratio"), std::string::npos);
  options = PaperLayeredGridOptions();
  options.finest_cell_size_m = 2e-3;  // 13 layers over a 9 m box.
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("max_num_layers"), std::string::npos);
  // Absurd cell sizes are refused by name before any arithmetic with them.
  for (double size : {1e-300,
                      1e-4,
                      1e6,
                      std::numeric_limits<double>::infinity(),
                      -1.0,
                      std::nan("")}) {
    SCOPED_TRACE(size);
    options = LayeredGridOptions();
    options.finest_cell_size_m = size;
    EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
    EXPECT_NE(error.find("finest_cell_size_m"), std::string::npos) << error;
    options = LayeredGridOptions();
    options.cell_size_m = size;
    EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
    EXPECT_NE(error.find("cell_size_m"), std::string::npos) << error;
  }
  options = LayeredGridOptions();
  options.regularization.min_eigenvalue_m2 =
      std::numeric_limits<double>::infinity();
  EXPECT_FALSE(LayeredGrid::Build(options, cloud, &grid, &error));
  EXPECT_NE(error.find("min_eigenvalue_m2"), std::string::npos) << error;
}

TEST(LayeredGrid, ExplicitCellSizeGivesOneLayerOfThatCell) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(9, 9, 3), 4000, 12);
  LayeredGridOptions options;
  options.cell_size_m = 1.5;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  ASSERT_EQ(grid.num_layers(), 1);
  EXPECT_EQ(grid.layer(1).cell_size(), 1.5);
  // floor(extent / k) + 1 cells per axis over the cloud's box.
  const Eigen::Vector3d extent = grid.bounds().sizes();
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(grid.layer(1).dims()(a),
              static_cast<int>(std::floor(extent(a) / 1.5)) + 1);
  }
  EXPECT_EQ(LayerCellSizes(options, extent), std::vector<double>{1.5});
}

TEST(LayeredGrid, FlatCloudStillBuilds) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 20.0);
  PointCloud plane;
  for (int i = 0; i < 5000; ++i)
    plane.Add(Eigen::Vector3d(u(rng), u(rng), 0.0));
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(
      LayeredGrid::Build(PaperLayeredGridOptions(), plane, &grid, &error))
      << error;
  ASSERT_FALSE(grid.layer(2).cells().empty());
  // A planar cell is regularised: smallest eigenvalue = largest / 100.
  const NdtCell& cell = grid.layer(2).cells().front();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cell.covariance);
  EXPECT_NEAR(es.eigenvalues()(0),
              es.eigenvalues()(2) / 100.0,
              1e-9 * es.eigenvalues()(2));
}

// The bundled KITTI frame `frame` (124668 points for frame 0).
PointCloud KittiScan(int frame) {
  PointCloud cloud;
  std::string error;
  const std::string path = testing::BundledDataPath(
      "kitti/pcd/00000" + std::to_string(frame) + ".pcd");
  EXPECT_TRUE(ReadPointCloud(path, &cloud, nullptr, &error)) << error;
  return cloud;
}

// Same bits, not just ==: -0.0 vs 0.0 or a different NaN would fail too.
template <typename Derived>
bool SameBits(const Eigen::DenseBase<Derived>& a,
              const Eigen::DenseBase<Derived>& b) {
  return std::memcmp(a.derived().data(),
                     b.derived().data(),
                     sizeof(double) * a.size()) == 0;
}

// Every layer of `a` and `b` holds the same cells, in the same order, with
// the same bits.
void ExpectIdenticalMaps(const LayeredGrid& a, const LayeredGrid& b) {
  EXPECT_TRUE(SameBits(a.bounds().min(), b.bounds().min()));
  EXPECT_TRUE(SameBits(a.bounds().max(), b.bounds().max()));
  ASSERT_EQ(a.num_layers(), b.num_layers());
  for (int i = 1; i <= a.num_layers(); ++i) {
    SCOPED_TRACE("layer " + std::to_string(i));
    const NdtLayer& la = a.layer(i);
    const NdtLayer& lb = b.layer(i);
    EXPECT_EQ(la.cell_size(), lb.cell_size());
    EXPECT_EQ(la.dims(), lb.dims());
    EXPECT_EQ(la.keys(), lb.keys());
    const LayerInfo& ia = a.layer_info()[static_cast<size_t>(i - 1)];
    const LayerInfo& ib = b.layer_info()[static_cast<size_t>(i - 1)];
    EXPECT_EQ(ia.occupied_cells, ib.occupied_cells);
    EXPECT_EQ(ia.sparse_cells, ib.sparse_cells);
    EXPECT_EQ(ia.degenerate_cells, ib.degenerate_cells);
    ASSERT_EQ(la.cells().size(), lb.cells().size());
    for (size_t c = 0; c < la.cells().size(); ++c) {
      const NdtCell& ca = la.cells()[c];
      const NdtCell& cb = lb.cells()[c];
      ASSERT_EQ(ca.count, cb.count) << "cell " << c;
      ASSERT_TRUE(SameBits(ca.mean, cb.mean)) << "cell " << c;
      ASSERT_TRUE(SameBits(ca.covariance, cb.covariance)) << "cell " << c;
      ASSERT_TRUE(SameBits(ca.information, cb.information)) << "cell " << c;
      ASSERT_TRUE(SameBits(ca.whitening, cb.whitening)) << "cell " << c;
    }
  }
}

TEST(LayeredGrid, ThreadsBuildTheSameMapOnKitti) {
  const PointCloud scan = KittiScan(0);
  ASSERT_EQ(scan.size(), 124668u);
  // The registration default (1.2 m, nested layers aggregated from the
  // finest),
  // a finer map, and q = 10 (every layer binned from the points).
  LayeredGridOptions registration;
  ASSERT_EQ(registration.finest_cell_size_m, 1.2);
  LayeredGridOptions fine = registration;
  fine.finest_cell_size_m = 0.5;
  LayeredGridOptions non_nested = PaperLayeredGridOptions();
  non_nested.division_constant = 10;
  non_nested.num_layers = 4;
  for (const LayeredGridOptions& options : {registration, fine, non_nested}) {
    SCOPED_TRACE("finest_cell_size_m " +
                 std::to_string(options.finest_cell_size_m) + ", q " +
                 std::to_string(options.division_constant));
    LayeredGrid serial;
    std::string error;
    ASSERT_TRUE(LayeredGrid::Build(options, scan, &serial, &error)) << error;
    ASSERT_GT(serial.layer_info().back().occupied_cells, 500u);
    for (int threads : {2, 3}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      LayeredGrid parallel;
      ASSERT_TRUE(LayeredGrid::Build(options, scan, threads, &parallel, &error))
          << error;
      ExpectIdenticalMaps(serial, parallel);
    }
  }
}

TEST(LayeredGrid, MoreThreadsThanCellsBuildTheSameMap) {
  // A few cells per layer: most threads get no cells to sum.
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 4, 1), 300, 10);
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.num_layers = 2;
  LayeredGrid serial, parallel;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &serial, &error)) << error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, 8, &parallel, &error))
      << error;
  ExpectIdenticalMaps(serial, parallel);
}

TEST(LayeredGrid, ThreadCountsOutsideOneTo256AreRefused) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(9, 9, 9), 500, 11);
  for (int threads : {0, -1, 257, 100000}) {
    SCOPED_TRACE(threads);
    LayeredGrid grid;
    std::string error;
    EXPECT_FALSE(LayeredGrid::Build(
        LayeredGridOptions(), cloud, threads, &grid, &error));
    EXPECT_NE(error.find("num_threads"), std::string::npos) << error;
    EXPECT_TRUE(grid.empty());
  }
}

TEST(LayeredGrid, MemoryBytesCoversTheCellsAndGrowsWithThem) {
  const PointCloud scan = KittiScan(0);
  EXPECT_EQ(LayeredGrid().MemoryBytes(), sizeof(LayeredGrid));
  size_t previous_cells = 0;
  size_t previous_bytes = 0;
  for (double finest_m : {4.0, 2.0, 1.0}) {
    SCOPED_TRACE("finest_cell_size_m " + std::to_string(finest_m));
    LayeredGridOptions options;
    options.finest_cell_size_m = finest_m;
    LayeredGrid grid;
    std::string error;
    ASSERT_TRUE(LayeredGrid::Build(options, scan, &grid, &error)) << error;
    size_t cells = 0;
    size_t layer_bytes = 0;
    for (int i = 1; i <= grid.num_layers(); ++i) {
      const NdtLayer& layer = grid.layer(i);
      const size_t n = layer.cells().size();
      cells += n;
      layer_bytes += layer.MemoryBytes();
      // Cells, keys and at least one index entry per cell.
      EXPECT_GE(layer.MemoryBytes(),
                sizeof(NdtLayer) +
                    n * (sizeof(NdtCell) + sizeof(int64_t) + sizeof(int32_t)));
    }
    EXPECT_GE(grid.MemoryBytes(), cells * sizeof(NdtCell));
    EXPECT_GT(grid.MemoryBytes(), layer_bytes);
    EXPECT_GT(cells, previous_cells);
    EXPECT_GT(grid.MemoryBytes(), previous_bytes);
    previous_cells = cells;
    previous_bytes = grid.MemoryBytes();
  }
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

TEST(LayeredGrid, FinestCellWeightingMakesCoarseCellsTheMixtureOfFineCells) {
  // 200 points near (1, 1, 1) and 20 near (3, 1, 1), plus a far corner that
  // makes the box 16 m: layers of 8, 4 and 2 m cells. The clusters have
  // finest (2 m) cells of their own and share a 4 m cell.
  std::mt19937 rng(21);
  std::normal_distribution<double> n(0.0, 0.1);
  PointCloud cloud;
  for (int i = 0; i < 200; ++i) {
    cloud.Add(Eigen::Vector3d(1 + n(rng), 1 + n(rng), 1 + n(rng)));
  }
  for (int i = 0; i < 20; ++i) {
    cloud.Add(Eigen::Vector3d(3 + n(rng), 1 + n(rng), 1 + n(rng)));
  }
  cloud.Add(Eigen::Vector3d(0, 0, 0));
  for (int i = 0; i < 5; ++i) cloud.Add(Eigen::Vector3d(16, 16, 16));
  LayeredGridOptions options = PaperLayeredGridOptions();
  options.num_layers = 3;
  LayeredGrid points, cells;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &points, &error)) << error;
  options.coarse_weighting = CoarseWeighting::FINEST_CELLS;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &cells, &error)) << error;
  ASSERT_NEAR(points.layer(3).cell_size(), 2.0, 1e-9);
  const Eigen::Vector3d dense(1, 1, 1), sparse(3, 1, 1);
  // The finest layer is the same either way.
  ASSERT_NE(points.layer(3).Lookup(dense), nullptr);
  EXPECT_EQ(points.layer(3).Lookup(dense)->mean,
            cells.layer(3).Lookup(dense)->mean);
  const Eigen::Vector3d mean_dense = points.layer(3).Lookup(dense)->mean;
  const Eigen::Vector3d mean_sparse = points.layer(3).Lookup(sparse)->mean;
  // Layer 2 (4 m): by points the mean sits near the dense cluster, by finest
  // cells halfway between the two clusters' means.
  const NdtCell* by_points = points.layer(2).Lookup(dense);
  const NdtCell* by_cells = cells.layer(2).Lookup(dense);
  ASSERT_NE(by_points, nullptr);
  ASSERT_NE(by_cells, nullptr);
  EXPECT_EQ(by_points->count, 221);
  EXPECT_EQ(by_cells->count, 221);
  EXPECT_NEAR(by_points->mean.x(), 1.18, 0.03);
  // (The corner at the origin is in the dense cluster's finest cell.)
  EXPECT_LT((by_cells->mean - (mean_dense + mean_sparse) / 2.0).norm(), 1e-12);
  // Its covariance spans the clusters: x variance ~ (2 m / 2)^2.
  EXPECT_GT(by_cells->covariance(0, 0), 0.8);
  EXPECT_LT(by_points->covariance(0, 0), 0.5);
  std::string name = CoarseWeightingToString(CoarseWeighting::FINEST_CELLS);
  CoarseWeighting parsed = CoarseWeighting::POINTS;
  EXPECT_TRUE(StringToCoarseWeighting("finest_cells", &parsed));
  EXPECT_EQ(parsed, CoarseWeighting::FINEST_CELLS);
  EXPECT_EQ(name, "FINEST_CELLS");
}

}  // namespace
}  // namespace mlndt

namespace mlndt {
namespace {

// The fraction of `cloud`'s points in cells of the map's finest layer that
// hold >= min_points points, counted here from the points (cells anchored at
// the box's minimum, the max face inside the last cell).
double FinestCoverage(const LayeredGrid& grid,
                      const PointCloud& cloud,
                      int min_points) {
  const NdtLayer& finest = grid.layer(grid.num_layers());
  std::map<std::array<int, 3>, int64_t> counts;
  for (const Eigen::Vector3d& p : cloud.points()) {
    std::array<int, 3> key;
    for (int a = 0; a < 3; ++a) {
      const int i = static_cast<int>(
          std::floor((p(a) - grid.bounds().min()(a)) / finest.cell_size()));
      key[static_cast<size_t>(a)] = std::min(i, finest.dims()(a) - 1);
    }
    ++counts[key];
  }
  int64_t covered = 0;
  for (const auto& entry : counts) {
    if (entry.second >= min_points) covered += entry.second;
  }
  return static_cast<double>(covered) / static_cast<double>(cloud.size());
}

TEST(LayeredGridCoverage, SparseCloudGetsTheFinestCellItCanFill) {
  // 3000 points in a 40 x 30 x 10 m box: 1.2 m derives 0.72 m cells, which
  // hold less than one point each.
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 30, 10), 3000, 7);
  LayeredGridOptions fixed;
  fixed.min_covered_fraction = 0.0;
  LayeredGridOptions derived = fixed;
  derived.min_covered_fraction = 0.5;
  LayeredGrid fixed_grid;
  LayeredGrid derived_grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(fixed, cloud, &fixed_grid, &error)) << error;
  ASSERT_TRUE(LayeredGrid::Build(derived, cloud, &derived_grid, &error))
      << error;
  EXPECT_EQ(fixed_grid.num_layers(), 5);
  EXPECT_LT(FinestCoverage(fixed_grid, cloud, 5), 0.5);
  ASSERT_LT(derived_grid.num_layers(), fixed_grid.num_layers());
  EXPECT_GE(FinestCoverage(derived_grid, cloud, 5), 0.5);
  // The finest layer that covers enough, not a coarser one: one layer more
  // would not.
  LayeredGridOptions one_finer = fixed;
  one_finer.finest_cell_size_m = 0.0;
  one_finer.num_layers = derived_grid.num_layers() + 1;
  LayeredGrid finer_grid;
  ASSERT_TRUE(LayeredGrid::Build(one_finer, cloud, &finer_grid, &error))
      << error;
  EXPECT_LT(FinestCoverage(finer_grid, cloud, 5), 0.5);
  EXPECT_NEAR(derived_grid.layer(derived_grid.num_layers()).cell_size(),
              finer_grid.layer(finer_grid.num_layers() - 1).cell_size(),
              1e-9);
}

TEST(LayeredGridCoverage, DenseCloudKeepsTheDerivedLayers) {
  // 30000 points in a 10 m cube: 0.625 m cells hold ~7 points each.
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10), 30000, 8);
  LayeredGridOptions fixed;
  fixed.min_covered_fraction = 0.0;
  LayeredGridOptions derived = fixed;
  derived.min_covered_fraction = 0.5;
  LayeredGrid fixed_grid;
  LayeredGrid derived_grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(fixed, cloud, &fixed_grid, &error)) << error;
  ASSERT_TRUE(LayeredGrid::Build(derived, cloud, &derived_grid, &error))
      << error;
  EXPECT_GE(FinestCoverage(fixed_grid, cloud, 5), 0.5);
  ASSERT_EQ(derived_grid.num_layers(), fixed_grid.num_layers());
  for (int i = 1; i <= fixed_grid.num_layers(); ++i) {
    EXPECT_EQ(
        derived_grid.layer_info()[static_cast<size_t>(i - 1)].occupied_cells,
        fixed_grid.layer_info()[static_cast<size_t>(i - 1)].occupied_cells);
  }
}

TEST(LayeredGridCoverage, GivenLayerCountOrCellSizeIsKept) {
  const PointCloud cloud =
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 30, 10), 3000, 7);
  LayeredGridOptions layers;
  layers.finest_cell_size_m = 0.0;
  layers.num_layers = 5;
  layers.min_covered_fraction = 1.0;
  LayeredGridOptions cell;
  cell.cell_size_m = 0.3;
  cell.min_covered_fraction = 1.0;
  LayeredGrid grid;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(layers, cloud, &grid, &error)) << error;
  EXPECT_EQ(grid.num_layers(), 5);
  ASSERT_TRUE(LayeredGrid::Build(cell, cloud, &grid, &error)) << error;
  ASSERT_EQ(grid.num_layers(), 1);
  EXPECT_EQ(grid.layer(1).cell_size(), 0.3);
}

TEST(LayeredGridCoverage, OutOfRangeFractionIsRefused) {
  LayeredGridOptions options;
  std::string error;
  options.min_covered_fraction = 1.5;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("min_covered_fraction"), std::string::npos) << error;
  options.min_covered_fraction = -0.1;
  EXPECT_FALSE(options.IsValid(&error));
}

}  // namespace
}  // namespace mlndt
