#include "mlndt/pipeline/map_builder.h"

#include <glog/logging.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/sampling/point_sampler.h"
#include "tests/testing/scratch_dir.h"
#include "tests/testing/synthetic_scene.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;

// Three scans of the street from three poses, points within 25 m, written
// as PCD files in their sensor frames.
struct Scans {
  std::vector<std::string> paths;
  std::vector<Isometry3d> world_from_scan;
  std::vector<PointCloud> clouds;  // As written (float32 round trip).
};

const Scans& StreetScans() {
  static const Scans* scans = [] {
    auto* s = new Scans;
    // One folder per process: ctest runs the tests of this file in parallel.
    const std::string dir = testing::ScratchPath("street_scans");
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (int k = 0; k < 3; ++k) {
      const Isometry3d world_from_scan = PoseVectorToIsometry(
          PoseVectorFromDegrees(-15.0 + 10.0 * k, 1.0, 1.8, 0, 0, 20.0 * k));
      const PointCloud world = testing::StreetScene(30000, 0.01, 20 + k);
      PointCloud scan;
      for (const Eigen::Vector3d& p : world.points()) {
        if ((p - world_from_scan.translation()).norm() < 25.0) {
          scan.Add(world_from_scan.inverse() * p);
        }
      }
      const std::string path = dir + "/" + std::to_string(k) + ".pcd";
      std::string error;
      CHECK(WritePointCloud(path, scan, &error)) << error;
      PointCloud read;
      CHECK(ReadPointCloud(path, &read, nullptr, &error)) << error;
      s->paths.push_back(path);
      s->world_from_scan.push_back(world_from_scan);
      s->clouds.push_back(read);
    }
    return s;
  }();
  return *scans;
}

// The merged cloud the builder should make: cropped, moved, in order.
PointCloud ExpectedMerge(const RangeFilterOptions& crop, size_t* cropped) {
  const Scans& scans = StreetScans();
  PointCloud merged;
  *cropped = 0;
  for (size_t k = 0; k < scans.clouds.size(); ++k) {
    for (const Eigen::Vector3d& p : scans.clouds[k].points()) {
      const double r = p.norm();
      if (r < crop.min_range_m ||
          (crop.max_range_m > 0.0 && r > crop.max_range_m)) {
        ++*cropped;
        continue;
      }
      merged.Add(scans.world_from_scan[k] * p);
    }
  }
  return merged;
}

RangeFilterOptions Crop(double min_range_m, double max_range_m) {
  RangeFilterOptions crop;
  crop.min_range_m = min_range_m;
  crop.max_range_m = max_range_m;
  crop.saturated_range_fraction = 0.0;
  return crop;
}

void ExpectSameMap(const LayeredGrid& a, const LayeredGrid& b) {
  ASSERT_EQ(a.num_layers(), b.num_layers());
  EXPECT_EQ(a.num_points(), b.num_points());
  for (int i = 1; i <= a.num_layers(); ++i) {
    ASSERT_EQ(a.layer(i).cells().size(), b.layer(i).cells().size());
    EXPECT_EQ(a.layer(i).keys(), b.layer(i).keys());
    for (size_t c = 0; c < a.layer(i).cells().size(); ++c) {
      ASSERT_EQ(a.layer(i).cells()[c].mean, b.layer(i).cells()[c].mean);
    }
  }
}

TEST(BuildMapFromScans, CropsMovesMergesAndBuilds) {
  const Scans& scans = StreetScans();
  MapBuildOptions options;
  options.range_filter = Crop(3.0, 20.0);
  LayeredGrid map;
  MapBuildSummary summary;
  std::vector<ProgressEvent> events;
  ProgressFunction progress(
      [&](const ProgressEvent& e) { events.push_back(e); });
  std::string error;
  ASSERT_TRUE(BuildMapFromScans(options,
                                scans.paths,
                                scans.world_from_scan,
                                &progress,
                                &map,
                                &summary,
                                &error))
      << error;
  ASSERT_EQ(events.size(), 3u);
  size_t kept = 0;
  for (size_t k = 0; k < events.size(); ++k) {
    EXPECT_EQ(events[k].index, k);
    EXPECT_EQ(events[k].done, k + 1);
    EXPECT_EQ(events[k].total, 3u);
    kept += std::stoul(events[k].status);  // "N points": kept after the crop.
    EXPECT_NE(events[k].status.find(" points"), std::string::npos);
  }
  size_t cropped = 0;
  const PointCloud expected = ExpectedMerge(options.range_filter, &cropped);
  EXPECT_EQ(summary.scans, 3u);
  EXPECT_EQ(
      summary.input_points,
      scans.clouds[0].size() + scans.clouds[1].size() + scans.clouds[2].size());
  EXPECT_GT(cropped, 0u);
  EXPECT_EQ(summary.cropped_points, cropped);
  EXPECT_EQ(kept, summary.input_points - cropped);
  EXPECT_EQ(summary.merged_points, expected.size());
  EXPECT_EQ(summary.map_points, expected.size());
  EXPECT_EQ(summary.map_bytes, map.MemoryBytes());
  EXPECT_EQ(summary.memory.map_bytes, map.MemoryBytes());
  EXPECT_GT(summary.build_time_s, 0.0);
  LayeredGrid reference;
  ASSERT_TRUE(LayeredGrid::Build(options.grid, expected, &reference, &error));
  ExpectSameMap(map, reference);
}

TEST(BuildMapFromScans, VoxelFiltersTheMergedCloud) {
  const Scans& scans = StreetScans();
  MapBuildOptions options;
  options.voxel_size_m = 0.3;
  LayeredGrid map;
  MapBuildSummary summary;
  std::string error;
  ASSERT_TRUE(BuildMapFromScans(options,
                                scans.paths,
                                scans.world_from_scan,
                                nullptr,
                                &map,
                                &summary,
                                &error))
      << error;
  size_t cropped = 0;
  const PointCloud filtered =
      VoxelDownsample(ExpectedMerge(Crop(0.0, 0.0), &cropped), 0.3);
  EXPECT_EQ(summary.cropped_points, 0u);
  EXPECT_LT(summary.map_points, summary.merged_points);
  EXPECT_EQ(summary.map_points, filtered.size());
  LayeredGrid reference;
  ASSERT_TRUE(LayeredGrid::Build(options.grid, filtered, &reference, &error));
  ExpectSameMap(map, reference);
}

// Each refusal names what is wrong and leaves the map as it was.
TEST(BuildMapFromScans, Refusals) {
  const Scans& scans = StreetScans();
  LayeredGrid map;
  MapBuildSummary summary;
  std::string error;
  MapBuildOptions options;
  auto build = [&](const std::vector<std::string>& paths,
                   const std::vector<Isometry3d>& poses) {
    return BuildMapFromScans(
        options, paths, poses, nullptr, &map, &summary, &error);
  };
  EXPECT_FALSE(build(scans.paths, {Isometry3d::Identity()}));
  EXPECT_NE(error.find("1 poses for 3 scans"), std::string::npos) << error;
  EXPECT_FALSE(build({}, {}));
  EXPECT_NE(error.find("no scans"), std::string::npos) << error;
  EXPECT_FALSE(
      build({scans.paths[0], "/nonexistent/scan.pcd"}, scans.world_from_scan));
  EXPECT_NE(error.find("/nonexistent/scan.pcd"), std::string::npos) << error;
  options.range_filter = Crop(500.0, 0.0);
  EXPECT_FALSE(build(scans.paths, scans.world_from_scan));
  EXPECT_NE(error.find("the range filter removed every point"),
            std::string::npos)
      << error;
  options = MapBuildOptions();
  options.voxel_size_m = -1.0;
  EXPECT_FALSE(build(scans.paths, scans.world_from_scan));
  EXPECT_NE(error.find("voxel_size_m"), std::string::npos) << error;
  options = MapBuildOptions();
  options.max_memory_bytes = 100000;  // The first scan does not fit.
  EXPECT_FALSE(build(scans.paths, scans.world_from_scan));
  EXPECT_NE(error.find("merging scan 0"), std::string::npos) << error;
  EXPECT_NE(error.find("memory limit of 100.0 kB"), std::string::npos) << error;
  // Issue 27 item 3: a 1e300 pose and a map without occupied cells.
  options = MapBuildOptions();
  std::vector<Isometry3d> huge = scans.world_from_scan;
  huge[1].translation().x() = 1e300;
  EXPECT_FALSE(build(scans.paths, huge));
  EXPECT_NE(error.find("the pose of scan 1 (" + scans.paths[1] +
                       "): translation (1e+300, "),
            std::string::npos)
      << error;
  options.grid.min_points_per_cell = 1000000;  // No cell gets that many.
  EXPECT_FALSE(build(scans.paths, scans.world_from_scan));
  EXPECT_NE(error.find("the map is not usable: the map has 0 occupied cells"),
            std::string::npos)
      << error;
  EXPECT_TRUE(map.empty());
}

// The merge fits but the map build does not: refused by the estimate.
TEST(BuildMapFromScans, RefusesAMapThatExceedsTheLimit) {
  const Scans& scans = StreetScans();
  MapBuildOptions options;
  LayeredGrid map;
  MapBuildSummary summary;
  std::string error;
  ASSERT_TRUE(BuildMapFromScans(options,
                                scans.paths,
                                scans.world_from_scan,
                                nullptr,
                                &map,
                                &summary,
                                &error));
  options.max_memory_bytes = summary.memory.total_bytes() - 1;
  LayeredGrid refused;
  EXPECT_FALSE(BuildMapFromScans(options,
                                 scans.paths,
                                 scans.world_from_scan,
                                 nullptr,
                                 &refused,
                                 &summary,
                                 &error));
  EXPECT_NE(error.find("exceeds the memory limit"), std::string::npos) << error;
  EXPECT_TRUE(refused.empty());
}

TEST(BuildMapFromCloud, FiltersAndBuildsButDoesNotCrop) {
  size_t cropped = 0;
  const PointCloud merged = ExpectedMerge(Crop(0.0, 0.0), &cropped);
  MapBuildOptions options;
  options.voxel_size_m = 0.5;
  LayeredGrid map;
  MapBuildSummary summary;
  std::string error;
  ASSERT_TRUE(BuildMapFromCloud(options, merged, &map, &summary, &error))
      << error;
  EXPECT_EQ(summary.input_points, merged.size());
  EXPECT_EQ(summary.map_points, VoxelDownsample(merged, 0.5).size());
  // A merged cloud has no sensor origin: the range filter does not apply.
  options.range_filter = Crop(500.0, 0.0);
  ASSERT_TRUE(BuildMapFromCloud(options, merged, &map, &summary, &error))
      << error;
  EXPECT_EQ(summary.map_points, VoxelDownsample(merged, 0.5).size());
}

}  // namespace
}  // namespace mlndt
