// ScanStore: scans read once, one map per (scan, map options) compared by
// value, rebuilt for other options, freed by ReleaseBefore.

#include "lab/runs/scan_store.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/testing/synthetic_sequence.h"

namespace mlndt {
namespace {

testing::SyntheticSequence ThreeScans(const std::string& name) {
  return testing::WriteSyntheticSequence(
      name, 3, 8000, testing::SmallStepMotion());
}

TEST(ScanStore, ReadsEachScanOnce) {
  ScanStore store(ThreeScans("store_reads").paths);
  ASSERT_EQ(store.size(), 3u);
  EXPECT_EQ(store.file_name(1), "000001.pcd");
  EXPECT_FALSE(store.HasCloud(0));
  std::string error;
  const PointCloud* first = store.Cloud(0, &error);
  ASSERT_NE(first, nullptr) << error;
  EXPECT_GT(first->size(), 0u);
  EXPECT_TRUE(store.HasCloud(0));
  EXPECT_EQ(store.Cloud(0, &error), first);
}

TEST(ScanStore, UnreadableScanIsAnErrorNamingTheFile) {
  ScanStore store({"/nonexistent/000000.pcd"});
  std::string error;
  EXPECT_EQ(store.Cloud(0, &error), nullptr);
  EXPECT_NE(error.find("/nonexistent/000000.pcd"), std::string::npos);
  double build_time_s = -1.0;
  EXPECT_EQ(store.Map(0, LayeredGridOptions(), 1, &build_time_s, &error),
            nullptr);
  EXPECT_EQ(store.NumMaps(0), 0u);
}

TEST(ScanStore, BuildsOncePerScanAndOptionsAndRebuildsForOtherOptions) {
  ScanStore store(ThreeScans("store_cache").paths);
  std::string error;
  double build_time_s = -1.0;
  const LayeredGridOptions options;
  const LayeredGrid* map = store.Map(0, options, 1, &build_time_s, &error);
  ASSERT_NE(map, nullptr) << error;
  EXPECT_GT(build_time_s, 0.0);
  EXPECT_EQ(store.num_maps_built(), 1u);

  // Equal options (another object, other threads): the same map, no build.
  LayeredGridOptions same = options;
  EXPECT_EQ(store.Map(0, same, 2, &build_time_s, &error), map);
  EXPECT_EQ(build_time_s, 0.0);
  EXPECT_EQ(store.num_maps_built(), 1u);

  // Other options: a second map of the same scan.
  LayeredGridOptions coarser = options;
  coarser.finest_cell_size_m = 4.0;
  ASSERT_NE(coarser, options);
  const LayeredGrid* other = store.Map(0, coarser, 1, &build_time_s, &error);
  ASSERT_NE(other, nullptr) << error;
  EXPECT_NE(other, map);
  EXPECT_GT(build_time_s, 0.0);
  EXPECT_EQ(store.num_maps_built(), 2u);
  EXPECT_EQ(store.NumMaps(0), 2u);
  EXPECT_EQ(other->options(), coarser);

  // Both stay cached.
  EXPECT_EQ(store.Map(0, options, 1, &build_time_s, &error), map);
  EXPECT_EQ(store.Map(0, coarser, 1, &build_time_s, &error), other);
  EXPECT_EQ(store.num_maps_built(), 2u);
}

TEST(ScanStore, FailedBuildIsNotCached) {
  ScanStore store(ThreeScans("store_bad_options").paths);
  LayeredGridOptions invalid;
  invalid.division_constant = 1;
  std::string error;
  double build_time_s = -1.0;
  EXPECT_EQ(store.Map(1, invalid, 1, &build_time_s, &error), nullptr);
  EXPECT_NE(error.find("000001.pcd: map: "), std::string::npos) << error;
  EXPECT_EQ(store.NumMaps(1), 0u);
  EXPECT_EQ(store.num_maps_built(), 0u);
}

TEST(ScanStore, ReleaseBeforeFreesEarlierScansOnly) {
  ScanStore store(ThreeScans("store_release").paths);
  std::string error;
  double build_time_s = 0.0;
  for (size_t i = 0; i < 3; ++i) {
    ASSERT_NE(store.Map(i, LayeredGridOptions(), 1, &build_time_s, &error),
              nullptr)
        << error;
  }
  store.ReleaseBefore(2);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_FALSE(store.HasCloud(i));
    EXPECT_EQ(store.NumMaps(i), 0u);
  }
  EXPECT_TRUE(store.HasCloud(2));
  EXPECT_EQ(store.NumMaps(2), 1u);
  // A freed scan is read and built again on demand.
  ASSERT_NE(store.Map(0, LayeredGridOptions(), 1, &build_time_s, &error),
            nullptr);
  EXPECT_EQ(store.num_maps_built(), 4u);
  store.ReleaseBefore(100);  // Past the end: everything.
  EXPECT_FALSE(store.HasCloud(2));
}

}  // namespace
}  // namespace mlndt
