#include "mlndt/grid/map_memory.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

// Points spread over a box, seeded, with both corners included.
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

// A wide, flat scene (ground with clusters of points) whose finest layer
// is too large for the dense table: the hash index is estimated.
PointCloud WideFlatCloud() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.05);
  PointCloud cloud;
  for (int c = 0; c < 400; ++c) {
    const Eigen::Vector3d centre(4000 * u(rng), 4000 * u(rng), 0.0);
    for (int i = 0; i < 40; ++i) {
      cloud.Add(centre + Eigen::Vector3d(3 * u(rng), 3 * u(rng), noise(rng)));
    }
  }
  cloud.Add(Eigen::Vector3d(0, 0, -5));
  cloud.Add(Eigen::Vector3d(4003, 4003, 25));
  return cloud;
}

// Checks the estimate against the map Build makes: geometry, cell counts
// and bytes.
void ExpectEstimateMatchesBuild(const LayeredGridOptions& options,
                                const PointCloud& cloud) {
  MapMemoryEstimate estimate;
  std::string error;
  ASSERT_TRUE(EstimateMapMemory(options, cloud, 0, &estimate, &error)) << error;
  LayeredGrid grid;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &grid, &error)) << error;
  EXPECT_TRUE(estimate.complete);
  ASSERT_EQ(static_cast<int>(estimate.layers.size()), grid.num_layers());
  size_t degenerate = 0;
  for (int i = 1; i <= grid.num_layers(); ++i) {
    SCOPED_TRACE("layer " + std::to_string(i));
    const LayerMemoryEstimate& e = estimate.layers[static_cast<size_t>(i - 1)];
    const LayerInfo& info = grid.layer_info()[static_cast<size_t>(i - 1)];
    EXPECT_EQ(e.layer, i);
    EXPECT_EQ(e.dims, grid.layer(i).dims());
    EXPECT_EQ(e.cell_size_m, grid.layer(i).cell_size());
    EXPECT_EQ(e.grid_cells, grid.layer(i).num_grid_cells());
    EXPECT_EQ(e.kept_cells, info.occupied_cells + info.degenerate_cells);
    EXPECT_EQ(e.touched_cells,
              info.occupied_cells + info.degenerate_cells + info.sparse_cells);
    if (info.degenerate_cells == 0) {
      EXPECT_EQ(e.bytes, grid.layer(i).MemoryBytes());
    }
    degenerate += info.degenerate_cells;
  }
  if (degenerate == 0) {
    EXPECT_EQ(estimate.map_bytes, grid.MemoryBytes());
  } else {
    EXPECT_GE(estimate.map_bytes, grid.MemoryBytes());
  }
  EXPECT_GE(estimate.build_peak_bytes, estimate.map_bytes);
  EXPECT_EQ(estimate.cloud_bytes,
            cloud.points().capacity() * sizeof(Eigen::Vector3d));
  EXPECT_EQ(estimate.total_bytes(),
            estimate.cloud_bytes + estimate.build_peak_bytes);
}

TEST(EstimateMapMemory, MatchesBuildOnAStreet) {
  const PointCloud street = testing::StreetScene(60000, 0.02, 5);
  ExpectEstimateMatchesBuild(LayeredGridOptions(), street);  // q = 8.
  LayeredGridOptions fine;
  fine.finest_cell_size_m = 0.5;
  ExpectEstimateMatchesBuild(fine, street);
  ExpectEstimateMatchesBuild(PaperLayeredGridOptions(), street);
}

// q not a perfect cube: every layer is binned from the points.
TEST(EstimateMapMemory, MatchesBuildWithoutNesting) {
  LayeredGridOptions options;
  options.division_constant = 10;
  options.finest_cell_size_m = 0.0;
  options.num_layers = 5;
  ExpectEstimateMatchesBuild(
      options,
      BoxCloud(
          Eigen::Vector3d(-30, -10, 0), Eigen::Vector3d(50, 10, 8), 30000, 2));
  options.division_constant = 27;  // A cube: nested by 3.
  options.num_layers = 3;
  ExpectEstimateMatchesBuild(
      options,
      BoxCloud(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(40, 40, 4), 30000, 4));
}

TEST(EstimateMapMemory, MatchesBuildForOneFixedCellLayer) {
  LayeredGridOptions options;
  options.cell_size_m = 1.5;
  ExpectEstimateMatchesBuild(options, testing::StreetScene(20000, 0.02, 6));
}

TEST(EstimateMapMemory, MatchesBuildWithAHashedIndex) {
  LayeredGridOptions options;
  options.finest_cell_size_m = 0.5;
  const PointCloud cloud = WideFlatCloud();
  MapMemoryEstimate estimate;
  std::string error;
  ASSERT_TRUE(EstimateMapMemory(options, cloud, 0, &estimate, &error));
  ASSERT_FALSE(estimate.layers.back().dense_index);  // The case under test.
  ExpectEstimateMatchesBuild(options, cloud);
}

// A limit below what the geometry alone needs is refused before counting;
// one between that and the full estimate after counting; both name the
// limit and the amounts.
TEST(EstimateMapMemory, RefusesWhatExceedsTheLimit) {
  const PointCloud street = testing::StreetScene(60000, 0.02, 5);
  MapMemoryEstimate full;
  std::string error;
  ASSERT_TRUE(
      EstimateMapMemory(LayeredGridOptions(), street, 0, &full, &error));
  ASSERT_TRUE(EstimateMapMemory(
      LayeredGridOptions(), street, full.total_bytes(), &full, &error));

  MapMemoryEstimate estimate;
  EXPECT_FALSE(EstimateMapMemory(
      LayeredGridOptions(), street, full.cloud_bytes, &estimate, &error));
  EXPECT_FALSE(estimate.complete);
  EXPECT_TRUE(estimate.exceeds_limit);
  EXPECT_NE(error.find("the map's geometry alone"), std::string::npos) << error;
  EXPECT_NE(error.find("exceeds the memory limit of"), std::string::npos)
      << error;

  EXPECT_FALSE(EstimateMapMemory(
      LayeredGridOptions(), street, full.total_bytes() - 1, &estimate, &error));
  EXPECT_TRUE(estimate.complete);
  EXPECT_TRUE(estimate.exceeds_limit);
  EXPECT_NE(error.find("the map of 5 layers"), std::string::npos) << error;
  EXPECT_NE(error.find(FormatBytes(double(full.total_bytes() - 1))),
            std::string::npos)
      << error;
}

// The counting pass stops before its own tables pass the limit: a fine
// grid over many points, with a limit the point buffers fit in.
TEST(EstimateMapMemory, RefusesWhenCountingAloneWouldExceedTheLimit) {
  LayeredGridOptions options;
  options.cell_size_m = 0.01;  // Every point its own cell, hashed.
  const PointCloud cloud = BoxCloud(
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(100, 100, 10), 200000, 8);
  MapMemoryEstimate estimate;
  std::string error;
  const size_t limit = cloud.points().capacity() * 24 + 200000 * 12 + 100000;
  EXPECT_FALSE(EstimateMapMemory(options, cloud, limit, &estimate, &error));
  EXPECT_TRUE(estimate.exceeds_limit);
  EXPECT_NE(error.find("counting the cells"), std::string::npos) << error;
}

TEST(EstimateMapMemory, RefusesWhatBuildRefuses) {
  MapMemoryEstimate estimate;
  std::string error;
  EXPECT_FALSE(EstimateMapMemory(
      LayeredGridOptions(), PointCloud(), 0, &estimate, &error));
  EXPECT_NE(error.find("empty"), std::string::npos) << error;
  PointCloud nan_cloud({{0, 0, 0}, {std::nan(""), 0, 0}});
  EXPECT_FALSE(
      EstimateMapMemory(LayeredGridOptions(), nan_cloud, 0, &estimate, &error));
  EXPECT_NE(error.find("non-finite"), std::string::npos) << error;
  PointCloud same({{1, 2, 3}, {1, 2, 3}});
  EXPECT_FALSE(
      EstimateMapMemory(LayeredGridOptions(), same, 0, &estimate, &error));
  EXPECT_NE(error.find("coincide"), std::string::npos) << error;
  LayeredGridOptions too_fine;
  too_fine.finest_cell_size_m = 0.001;
  EXPECT_FALSE(EstimateMapMemory(
      too_fine, testing::StreetScene(1000, 0.02, 1), 0, &estimate, &error));
  EXPECT_NE(error.find("max_num_layers"), std::string::npos) << error;
  LayeredGridOptions invalid;
  invalid.division_constant = 1;
  EXPECT_FALSE(EstimateMapMemory(
      invalid, testing::StreetScene(1000, 0.02, 1), 0, &estimate, &error));
  EXPECT_NE(error.find("division_constant"), std::string::npos) << error;
  // Refused for the cloud or the options, not for memory, even with a limit.
  EXPECT_FALSE(EstimateMapMemory(
      LayeredGridOptions(), same, size_t{1000}, &estimate, &error));
  EXPECT_FALSE(estimate.exceeds_limit);
}

TEST(FormatBytes, Units) {
  EXPECT_EQ(FormatBytes(512), "512 B");
  EXPECT_EQ(FormatBytes(12345), "12.3 kB");
  EXPECT_EQ(FormatBytes(456.7e6), "456.7 MB");
  EXPECT_EQ(FormatBytes(1.234e9), "1.23 GB");
}

}  // namespace
}  // namespace mlndt
