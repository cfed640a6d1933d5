#pragma once

// Builds a layered NDT map of a place from many scans: each scan is read in
// turn, cropped by range in its own sensor frame, moved into the world frame
// with its world_from_scan pose and appended; the merged cloud is
// voxel-filtered (VoxelDownsample, one centroid per voxel) and the map is
// built from it (LayeredGrid::Build). Or from one cloud already in the
// world frame.
//
// Memory is checked before each large allocation against
// MapBuildOptions::max_memory_bytes: the merged cloud before it grows, the
// voxel filter's tables (an upper bound: 12 bytes a point and 88 a voxel,
// at most one voxel a point), and the map build (EstimateMapMemory,
// grid/map_memory.h). A build that would not fit fails with a message that
// says how much it needs, before allocating it.

#include <cstddef>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/common/progress.h"
#include "mlndt/common/result_table.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/grid/map_memory.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {

// 8 GB: what one build may hold by default (10^9 bytes a GB).
constexpr size_t kDefaultMapMemoryLimitBytes = size_t{8000000000};

struct MapBuildOptions {
  // The map (cell sizes, q, min points per cell, regularisation).
  LayeredGridOptions grid;
  // Returns of every scan dropped by range from its sensor (range_filter.h;
  // BuildMapFromScans only: a merged cloud has no sensor origin).
  RangeFilterOptions range_filter;
  // Voxel edge of the filter of the merged cloud [m]; 0 = no filter.
  // 0, or in [1e-3, 1e3].
  double voxel_size_m = 0.0;
  // Memory the build may hold at once [bytes]: the merged cloud plus the
  // voxel filter's or the map build's working memory; 0 = no limit.
  size_t max_memory_bytes = kDefaultMapMemoryLimitBytes;
  // Threads of LayeredGrid::Build. In [1, 256].
  int num_threads = 1;

  bool IsValid(std::string* error) const;
};

struct MapBuildSummary {
  size_t scans = 0;         // Scans merged.
  size_t input_points = 0;  // Finite points read (or given).
  // Indices of the scans that gave no finite point (all NaN, or empty): they
  // add nothing to the map; the caller reports them.
  std::vector<size_t> scans_without_points;
  size_t cropped_points = 0;  // Removed by the range crop.
  size_t merged_points = 0;   // In the merged cloud.
  size_t map_points = 0;      // After the voxel filter: the map's input.
  MapMemoryEstimate memory;   // Of the map build (map_memory.h).
  size_t map_bytes = 0;       // LayeredGrid::MemoryBytes() of the map.
  double read_time_s = 0.0;   // Reading, cropping and moving the scans.
  double voxel_time_s = 0.0;
  double estimate_time_s = 0.0;  // EstimateMapMemory.
  double build_time_s = 0.0;     // LayeredGrid::Build.
  double total_time_s = 0.0;
};

// MapBuildSummary's fields (result_table.h), the memory estimate's table
// nested: mlndt_map's --output_json and docs/json_schema.md come from it.
const ResultTable& MapBuildSummaryTable();

// Reads scan_paths[k] (any format ReadPointCloud reads), crops it, maps it
// with world_from_scan[k] and merges it, for every k; then filters and
// builds. world_from_scan needs a pose for every scan (extra poses are
// ignored), each a rigid transform by ToRigidTransform
// (mlndt/common/rigid_transform.h: no 1e300 translation). `progress` (may
// be null, not owned) hears of each scan once it is merged: its index and
// "N points" kept. False with *error (naming the file, the pose, the option or
// the memory needed) on invalid options, a bad pose, a scan that cannot be
// read, no points left, what exceeds the memory limit, or a map that
// CheckMapUsable (grid/map_check.h) refuses (0 occupied cells); *map is
// then unchanged.
bool BuildMapFromScans(const MapBuildOptions& options,
                       const std::vector<std::string>& scan_paths,
                       const std::vector<Isometry3d>& world_from_scan,
                       ProgressCallback* progress,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error);

// The same with scan k loaded by `load_scan` (a ROS bag, ...); scan_names
// name the scans in messages, one per scan.
bool BuildMapFromScans(const MapBuildOptions& options,
                       const std::vector<std::string>& scan_names,
                       const ScanLoader& load_scan,
                       const std::vector<Isometry3d>& world_from_scan,
                       ProgressCallback* progress,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error);

// The same from one cloud already in the world frame (a merged map cloud):
// filters and builds (and refuses an unusable map, as above). options.crop must
// be off (a merged cloud has no sensor origin).
bool BuildMapFromCloud(const MapBuildOptions& options,
                       PointCloud cloud,
                       LayeredGrid* map,
                       MapBuildSummary* summary,
                       std::string* error);

}  // namespace mlndt
