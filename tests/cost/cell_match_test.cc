#include "mlndt/cost/cell_match.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/test_data.h"

namespace mlndt {
namespace {

// MatchCell as first written: 27 bounds-checked CellAt calls.
const NdtCell* MatchCellByCellAt(const NdtLayer& layer,
                                 const Eigen::Vector3d& point,
                                 UnmatchedPolicy policy) {
  const Eigen::Vector3i ijk = layer.CellCoordinates(point);
  const NdtCell* own = layer.CellAt(ijk);
  if (own != nullptr || policy == UnmatchedPolicy::ZERO_RESIDUAL) return own;
  const NdtCell* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const NdtCell* cell = layer.CellAt(ijk + Eigen::Vector3i(dx, dy, dz));
        if (cell == nullptr) continue;
        const Eigen::Vector3d e = point - cell->mean;
        const double distance = e.dot(cell->information * e);
        if (distance < best_distance) {
          best_distance = distance;
          best = cell;
        }
      }
    }
  }
  return best;
}

PointCloud ReadBundled(const std::string& relative) {
  PointCloud cloud;
  std::string error;
  EXPECT_TRUE(ReadPointCloud(
      testing::BundledDataPath(relative), &cloud, nullptr, &error))
      << error;
  return cloud;
}

// Every sampled point of `input`, shifted by random offsets of up to a few
// metres (so that many land in empty cells, near borders and outside the
// grid), is matched on every layer of `reference`'s map as the
// straightforward search matches it.
void ExpectSameMatches(const std::string& reference, const std::string& input) {
  LayeredGrid map;
  PointCloud sampled;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(
      LayeredGridOptions(), ReadBundled(reference), &map, &error))
      << error;
  ASSERT_TRUE(SamplePoints(
      SamplingOptions(), ReadBundled(input), &sampled, nullptr, &error))
      << error;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> shift(-3.0, 3.0);
  size_t nearest_matches = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::Vector3d offset =
        trial == 0 ? Eigen::Vector3d::Zero()
                   : Eigen::Vector3d(shift(rng), shift(rng), shift(rng));
    for (int l = 1; l <= map.num_layers(); ++l) {
      const NdtLayer& layer = map.layer(l);
      for (const Eigen::Vector3d& p : sampled.points()) {
        const Eigen::Vector3d q = p + offset;
        for (UnmatchedPolicy policy :
             {UnmatchedPolicy::ZERO_RESIDUAL, UnmatchedPolicy::NEAREST_CELL}) {
          const NdtCell* expected = MatchCellByCellAt(layer, q, policy);
          ASSERT_EQ(MatchCell(layer, q, policy), expected)
              << "layer " << l << " point " << q.transpose();
          if (policy == UnmatchedPolicy::NEAREST_CELL && expected != nullptr &&
              layer.Lookup(q) == nullptr) {
            ++nearest_matches;
          }
        }
      }
    }
  }
  // The comparison covered the nearest-cell search, not only own cells.
  EXPECT_GT(nearest_matches, 1000u);
}

TEST(MatchCell, SameCellsAsTheBoundsCheckedSearchOnKitti) {
  ExpectSameMatches("kitti/pcd/000000.pcd", "kitti/pcd/000001.pcd");
}

TEST(MatchCell, SameCellsAsTheBoundsCheckedSearchOnKoide3) {
  ExpectSameMatches("koide3/251370668.pcd", "koide3/251371071.pcd");
}

TEST(MatchCell, OwnCellFirstThenNearestNeighbourThenNothing) {
  // Two occupied cells of a 1 m grid: points around (0.5, 0.5, 0.5) and
  // around (2.5, 0.5, 0.5); cell (1, 0, 0) between them is empty.
  PointCloud cloud;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (double x : {0.5, 2.5}) {
    for (int i = 0; i < 50; ++i) {
      cloud.Add(Eigen::Vector3d(x + noise(rng),
                                0.5 + 2.0 * noise(rng),
                                0.5 + 2.0 * noise(rng))
                    .cwiseMax(0.01)
                    .cwiseMin(2.99));
    }
  }
  LayeredGridOptions options;
  options.cell_size_m = 1.0;
  LayeredGrid map;
  std::string error;
  ASSERT_TRUE(LayeredGrid::Build(options, cloud, &map, &error)) << error;
  const NdtLayer& layer = map.layer(1);
  const NdtCell* left = layer.Lookup(Eigen::Vector3d(0.5, 0.5, 0.5));
  const NdtCell* right = layer.Lookup(Eigen::Vector3d(2.5, 0.5, 0.5));
  ASSERT_NE(left, nullptr);
  ASSERT_NE(right, nullptr);
  // Points in the empty middle cell, nearer the left or the right one.
  const auto at = [&](double x) {
    return Eigen::Vector3d(
        layer.origin().x() + x, left->mean.y(), left->mean.z());
  };
  ASSERT_EQ(layer.Lookup(at(1.1)), nullptr);
  ASSERT_EQ(layer.Lookup(at(1.9)), nullptr);
  EXPECT_EQ(MatchCell(layer, at(1.1), UnmatchedPolicy::NEAREST_CELL), left);
  EXPECT_EQ(MatchCell(layer, at(1.9), UnmatchedPolicy::NEAREST_CELL), right);
  EXPECT_EQ(MatchCell(layer, at(1.1), UnmatchedPolicy::ZERO_RESIDUAL), nullptr);
  EXPECT_EQ(MatchCell(layer, left->mean, UnmatchedPolicy::ZERO_RESIDUAL), left);
  // Two cells beyond the grid: no neighbour is occupied.
  EXPECT_EQ(MatchCell(layer, at(6.0), UnmatchedPolicy::NEAREST_CELL), nullptr);
}

}  // namespace
}  // namespace mlndt
