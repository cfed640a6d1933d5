#pragma once

// The scans of a sequence folder for the evaluation tools (mlndt_sequence,
// mlndt_experiments): a store that reads each scan once and builds each
// scan's reference map once. Listing the scans and reading ground-truth
// poses are in mlndt/eval/dataset.h.
//
// Map reuse follows ML-NDT Section 4.3: in a sequence the input scan at t_i
// is the reference at t_{i+1}, so its map is built once and then reused;
// the store also reuses maps across repeated runs on the same scans (the
// experiments run many configurations over the same pairs).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/common/timer.h"
#include "mlndt/eval/dataset.h"
#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace tools {

// A key that differs whenever two grid options can give different maps.
inline std::string GridOptionsKey(const LayeredGridOptions& o) {
  char key[256];
  std::snprintf(key,
                sizeof(key),
                "q%d n%d f%.17g c%.17g m%d p%d r%.17g e%.17g",
                o.division_constant,
                o.num_layers,
                o.finest_cell_size_m,
                o.cell_size_m,
                o.max_num_layers,
                o.min_points_per_cell,
                o.regularization.min_eigenvalue_ratio,
                o.regularization.min_eigenvalue_m2);
  return key;
}

// Scans read on first use and maps built on first use, by scan index.
// Not thread-safe.
class ScanStore {
 public:
  explicit ScanStore(std::vector<std::string> paths)
      : paths_(std::move(paths)),
        clouds_(paths_.size()),
        maps_(paths_.size()) {}

  size_t size() const { return paths_.size(); }
  const std::string& path(size_t i) const { return paths_.at(i); }
  std::string file_name(size_t i) const {
    return std::filesystem::path(paths_.at(i)).filename().string();
  }

  // The cloud of scan i; null with *error when it cannot be read or is empty.
  const PointCloud* Cloud(size_t i, std::string* error) {
    if (clouds_.at(i) == nullptr) {
      auto cloud = std::make_unique<PointCloud>();
      if (!ReadPointCloud(paths_[i], cloud.get(), nullptr, error))
        return nullptr;
      if (cloud->size() == 0) {
        *error = paths_[i] + ": no finite points";
        return nullptr;
      }
      clouds_[i] = std::move(cloud);
    }
    return clouds_[i].get();
  }

  // The layered map of scan i built with `options`. *build_time_s is the
  // time spent building it in this call: 0 when the map was built before.
  const LayeredGrid* Map(size_t i,
                         const LayeredGridOptions& options,
                         double* build_time_s,
                         std::string* error) {
    *build_time_s = 0.0;
    std::unique_ptr<LayeredGrid>& slot = maps_.at(i)[GridOptionsKey(options)];
    if (slot == nullptr) {
      const PointCloud* cloud = Cloud(i, error);
      if (cloud == nullptr) return nullptr;
      const double start = NowSeconds();
      auto grid = std::make_unique<LayeredGrid>();
      if (!LayeredGrid::Build(options, *cloud, grid.get(), error)) {
        *error = paths_[i] + ": map: " + *error;
        maps_[i].erase(GridOptionsKey(options));
        return nullptr;
      }
      *build_time_s = NowSeconds() - start;
      slot = std::move(grid);
    }
    return slot.get();
  }

  // Frees the clouds and maps of scans before `first` (a sequence run that
  // has moved past them).
  void ReleaseBefore(size_t first) {
    for (size_t i = 0; i < std::min(first, paths_.size()); ++i) {
      clouds_[i].reset();
      maps_[i].clear();
    }
  }

 private:
  std::vector<std::string> paths_;
  std::vector<std::unique_ptr<PointCloud>> clouds_;
  // Per scan: grid options key -> map.
  std::vector<std::map<std::string, std::unique_ptr<LayeredGrid>>> maps_;
};

}  // namespace tools
}  // namespace mlndt
