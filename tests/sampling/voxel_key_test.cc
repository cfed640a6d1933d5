// Voxel keys (floor per axis, range checks) and GroupPointsByVoxel's order.

#include "mlndt/sampling/voxel_key.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace mlndt {
namespace {

TEST(ComputeVoxelKey, FloorsEachAxis) {
  VoxelKey key;
  ASSERT_TRUE(ComputeVoxelKey(Eigen::Vector3d(0.5, -0.5, 2.0), 1.0, &key));
  EXPECT_EQ(key.x, 0);
  EXPECT_EQ(key.y, -1);
  EXPECT_EQ(key.z, 2);
  ASSERT_TRUE(ComputeVoxelKey(Eigen::Vector3d(4e6, -4e6, 0.1), 0.5, &key));
  EXPECT_EQ(key.x, 8000000);
  EXPECT_EQ(key.y, -8000000);
  EXPECT_EQ(key.z, 0);
  EXPECT_TRUE(VoxelMinCorner(key, 0.5).isApprox(Eigen::Vector3d(4e6, -4e6, 0)));
  EXPECT_TRUE(VoxelCenter(key, 0.5).isApprox(
      Eigen::Vector3d(4e6 + 0.25, -4e6 + 0.25, 0.25)));
}

TEST(ComputeVoxelKey, RejectsNonFiniteAndOutOfRange) {
  VoxelKey key;
  key.x = 7;
  EXPECT_FALSE(ComputeVoxelKey(
      Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0),
      1.0,
      &key));
  EXPECT_FALSE(ComputeVoxelKey(Eigen::Vector3d(1e300, 0, 0), 1.0, &key));
  EXPECT_EQ(key.x, 7);  // Untouched.
}

TEST(GroupPointsByVoxel, FirstAppearanceOrderAndInputOrderInside) {
  const std::vector<Eigen::Vector3d> points = {{0.1, 0.1, 0.1},
                                               {5.5, 0.1, 0.1},
                                               {0.9, 0.2, 0.3},
                                               {std::nan(""), 0, 0},
                                               {5.1, 0.9, 0.9},
                                               {-0.5, 0, 0}};
  VoxelGroups groups;
  GroupPointsByVoxel(points, 1.0, &groups);
  ASSERT_EQ(groups.num_voxels(), 3u);
  EXPECT_EQ(groups.num_skipped, 1u);
  EXPECT_EQ(groups.first_skipped_index, 3u);
  EXPECT_EQ(groups.keys[0].x, 0);
  EXPECT_EQ(groups.keys[1].x, 5);
  EXPECT_EQ(groups.keys[2].x, -1);
  ASSERT_EQ(groups.num_points(0), 2u);
  EXPECT_EQ(groups.point_indices[groups.offsets[0]], 0u);
  EXPECT_EQ(groups.point_indices[groups.offsets[0] + 1], 2u);
  ASSERT_EQ(groups.num_points(1), 2u);
  EXPECT_EQ(groups.point_indices[groups.offsets[1]], 1u);
  EXPECT_EQ(groups.point_indices[groups.offsets[1] + 1], 4u);
  EXPECT_EQ(groups.num_points(2), 1u);
}

TEST(GroupPointsByVoxel, ManyVoxelsGrowTheTable) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 5000; ++i) points.emplace_back(i + 0.5, 0.5, 0.5);
  VoxelGroups groups;
  GroupPointsByVoxel(points, 1.0, &groups);
  ASSERT_EQ(groups.num_voxels(), 5000u);
  for (size_t v = 0; v < groups.num_voxels(); ++v) {
    EXPECT_EQ(groups.keys[v].x, static_cast<int64_t>(v));
  }
}

}  // namespace
}  // namespace mlndt
