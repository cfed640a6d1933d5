#include "mlndt/pipeline/map_builder.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "mlndt/cloud/io.h"
#include "mlndt/common/rigid_transform.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/map_check.h"
#include "mlndt/pipeline/pipeline_option_tables.h"
#include "mlndt/sampling/point_sampler.h"

namespace mlndt {
namespace {

constexpr size_t kPointBytes = sizeof(Eigen::Vector3d);

// Upper bound of VoxelDownsample's working memory (sampling/voxel_key.h's
// GroupPointsByVoxel plus the output): per point a voxel id and an index
// (12 bytes); per voxel its key, count, offset and cursor, two hash slots
// and the output point (88 bytes, push_back capacity included). There are at
// most min(points, voxels of the bounding box) voxels.
size_t VoxelFilterBytes(const PointCloud& cloud, double voxel_size_m) {
  const size_t n = cloud.size();
  const Eigen::Vector3d cells =
      (BoundingBox(cloud).sizes() / voxel_size_m).array().floor() + 1.0;
  const double box_voxels = cells.prod();
  const size_t voxels =
      box_voxels < static_cast<double>(n) ? static_cast<size_t>(box_voxels) : n;
  return n * 12 + voxels * 88;
}

// Filters `cloud` and builds the map, checking the memory first.
bool FilterAndBuild(const MapBuildOptions& options,
                    PointCloud cloud,
                    LayeredGrid* map,
                    MapBuildSummary* summary,
                    std::string* error) {
  const size_t limit = options.max_memory_bytes;
  summary->merged_points = cloud.size();
  if (cloud.empty()) {
    *error = "no points left to build the map from" +
             std::string(summary->cropped_points > 0
                             ? " (the range filter removed every point)"
                             : "");
    return false;
  }
  if (options.voxel_size_m > 0.0) {
    const double start = NowSeconds();
    const size_t cloud_bytes = cloud.points().capacity() * kPointBytes;
    const size_t filter_bytes = VoxelFilterBytes(cloud, options.voxel_size_m);
    if (limit > 0 && cloud_bytes + filter_bytes > limit) {
      *error = "the voxel filter of " + std::to_string(cloud.size()) +
               " points: the cloud (" + FormatBytes(double(cloud_bytes)) +
               ") plus up to " + FormatBytes(double(filter_bytes)) +
               " exceeds the memory limit of " + FormatBytes(double(limit));
      return false;
    }
    cloud = VoxelDownsample(cloud, options.voxel_size_m);
    summary->voxel_time_s = NowSeconds() - start;
  }
  summary->map_points = cloud.size();

  double start = NowSeconds();
  if (!EstimateMapMemory(options.grid, cloud, limit, &summary->memory, error)) {
    return false;
  }
  summary->estimate_time_s = NowSeconds() - start;
  start = NowSeconds();
  LayeredGrid built;
  if (!LayeredGrid::Build(
          options.grid, cloud, options.num_threads, &built, error)) {
    return false;
  }
  // A map without cells (or of absurd size) is refused here, not written
  // and found unusable later (map_check.h).
  if (!CheckMapUsable(built, error)) {
    *error = "the map is not usable: " + *error;
    return false;
  }
  summary->build_time_s = NowSeconds() - start;
  summary->map_bytes = built.MemoryBytes();
  *map = std::move(built);
  return true;
}

}  // namespace

bool MapBuildOptions::IsValid(std::string* error) const {
  return grid.IsValid(error) && range_filter.IsValid(error) &&
         MapBuildOwnOptionsTable().Check(*this, error);
}

bool BuildMapFromScans(const MapBuildOptions& options,
                       const std::vector<std::string>& scan_paths,
                       const ScanLoader& load_scan,
                       const std::vector<Isometry3d>& world_from_scan,
                       ProgressCallback* progress,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error) {
  CHECK(map != nullptr);
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  const double start = NowSeconds();
  *summary = MapBuildSummary();
  if (!options.IsValid(error)) return false;
  if (scan_paths.empty()) {
    *error = "no scans to build the map from";
    return false;
  }
  if (world_from_scan.size() < scan_paths.size()) {
    *error = std::to_string(world_from_scan.size()) + " poses for " +
             std::to_string(scan_paths.size()) +
             " scans: every scan needs a world_from_scan pose";
    return false;
  }
  for (size_t k = 0; k < scan_paths.size(); ++k) {
    Isometry3d rigid;
    std::string problem;
    if (!ToRigidTransform(world_from_scan[k].matrix(), &rigid, &problem)) {
      *error = "the pose of scan " + std::to_string(k) + " (" + scan_paths[k] +
               "): " + problem;
      return false;
    }
  }
  const size_t limit = options.max_memory_bytes;
  std::vector<Eigen::Vector3d> merged;
  PointCloud scan;
  for (size_t k = 0; k < scan_paths.size(); ++k) {
    if (!load_scan(k, &scan, error)) return false;
    summary->input_points += scan.size();
    if (scan.empty()) summary->scans_without_points.push_back(k);
    const size_t read = scan.size();
    scan = FilterByRange(options.range_filter, scan, nullptr);
    summary->cropped_points += read - scan.size();
    // Grow the merged cloud by doubling, refusing a growth that would not
    // fit (the old and the new buffer and this scan are alive together).
    const size_t needed = merged.size() + scan.size();
    if (needed > merged.capacity()) {
      const size_t capacity = std::max(needed, 2 * merged.capacity());
      const size_t bytes =
          (merged.capacity() + capacity + scan.size()) * kPointBytes;
      if (limit > 0 && bytes > limit) {
        *error = "merging scan " + std::to_string(k) + " (" + scan_paths[k] +
                 "): the merged cloud of " + std::to_string(needed) +
                 " points needs " + FormatBytes(double(bytes)) +
                 " while it grows, more than the memory limit of " +
                 FormatBytes(double(limit)) +
                 "; crop the scans (max range) or raise the limit";
        return false;
      }
      merged.reserve(capacity);
    }
    const Isometry3d& pose = world_from_scan[k];
    for (const Eigen::Vector3d& p : scan.points()) merged.push_back(pose * p);
    ++summary->scans;
    ReportProgress(
        progress,
        {k, k + 1, scan_paths.size(), std::to_string(scan.size()) + " points"});
  }
  scan = PointCloud();
  summary->read_time_s = NowSeconds() - start;
  const bool ok = FilterAndBuild(
      options, PointCloud(std::move(merged)), map, summary, error);
  summary->total_time_s = NowSeconds() - start;
  return ok;
}
bool BuildMapFromScans(const MapBuildOptions& options,
                       const std::vector<std::string>& scan_paths,
                       const std::vector<Isometry3d>& world_from_scan,
                       ProgressCallback* progress,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error) {
  const ScanLoader read = [&](size_t k, PointCloud* scan, std::string* e) {
    return ReadPointCloud(scan_paths[k], scan, nullptr, e);
  };
  return BuildMapFromScans(options,
                           scan_paths,
                           read,
                           world_from_scan,
                           progress,
                           map,
                           summary,
                           error);
}

bool BuildMapFromCloud(const MapBuildOptions& options,
                       PointCloud cloud,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error) {
  CHECK(map != nullptr);
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  const double start = NowSeconds();
  *summary = MapBuildSummary();
  if (!options.IsValid(error)) return false;
  summary->input_points = cloud.size();
  const bool ok =
      FilterAndBuild(options, std::move(cloud), map, summary, error);
  summary->total_time_s = NowSeconds() - start;
  return ok;
}

}  // namespace mlndt
