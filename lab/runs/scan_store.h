#pragma once

// The scans of a sequence: a store that reads each scan once and builds each
// scan's reference map once per set of map options. Listing the scans and
// reading ground-truth poses are in lab/eval/dataset.h.
//
// Map reuse follows ML-NDT Section 4.3: in a sequence the input scan at t_i
// is the reference at t_{i+1}, so its map is built once and then reused. The
// store also reuses maps across repeated runs on the same scans (experiments
// run many configurations over the same pairs): its cache holds one map per
// (scan, LayeredGridOptions), options compared with operator==
// (layered_grid.h), and builds a new map for options that differ.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {

// Scans read on first use and maps built on first use, by scan index.
// Not thread-safe. Returned pointers are owned by the store and stay valid
// until ReleaseBefore frees that scan or the store is destroyed.
class ScanStore {
 public:
  explicit ScanStore(std::vector<std::string> paths);
  // Scans from `load` (a ROS bag, tools/cli/scan_input.h) instead of
  // files; `names` name them in messages and reports, one per scan.
  ScanStore(std::vector<std::string> names, ScanLoader load);

  size_t size() const { return paths_.size(); }
  const std::string& path(size_t i) const { return paths_.at(i); }
  // The file name of scan i, without its folder.
  std::string file_name(size_t i) const;

  // The cloud of scan i; null with *error when it cannot be read or is empty.
  const PointCloud* Cloud(size_t i, std::string* error);

  // The layered map of scan i built with `options` on `num_threads` threads
  // (>= 1; the map does not depend on it, see LayeredGrid::Build).
  // *build_time_s is the time spent building it in this call: 0 when the map
  // was built before. Null with *error when the scan cannot be read or the
  // map cannot be built.
  const LayeredGrid* Map(size_t i,
                         const LayeredGridOptions& options,
                         int num_threads,
                         double* build_time_s,
                         std::string* error);

  // Frees the clouds and maps of scans before `first` (a sequence run that
  // has moved past them).
  void ReleaseBefore(size_t first);

  // For tests and reports: whether scan i's cloud is held, how many maps of
  // scan i are held, and how many maps the store has built in all.
  bool HasCloud(size_t i) const { return clouds_.at(i) != nullptr; }
  size_t NumMaps(size_t i) const { return maps_.at(i).size(); }
  size_t num_maps_built() const { return num_maps_built_; }

 private:
  using CachedMap =
      std::pair<LayeredGridOptions, std::unique_ptr<const LayeredGrid>>;

  std::vector<std::string> paths_;
  ScanLoader load_;  // Empty: read paths_ with ReadPointCloud.
  std::vector<std::unique_ptr<const PointCloud>> clouds_;
  std::vector<std::vector<CachedMap>> maps_;  // Per scan.
  size_t num_maps_built_ = 0;
};

}  // namespace mlndt
