#pragma once

// The scans of a sequence folder for the evaluation tools (mlndt_sequence,
// mlndt_experiments): listing, ground-truth poses, and a store that reads
// each scan once and builds each scan's reference map once.
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

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace tools {

// Lists the regular files directly in `dir` whose extension is a cloud
// format (cloud_format.h), sorted by file name. Files that are the same as a
// path in `exclude` (pose or calibration files kept beside the scans; .txt
// is also a cloud extension) are left out. False with *error when the folder
// cannot be read or holds no scans.
inline bool ListScanFiles(const std::string& dir,
                          const std::vector<std::string>& exclude,
                          std::vector<std::string>* paths,
                          std::string* error) {
  namespace fs = std::filesystem;
  paths->clear();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    *error = dir + ": not a folder";
    return false;
  }
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::error_code file_ec;
    if (!entry.is_regular_file(file_ec)) continue;
    CloudFormat format;
    std::string ignored;
    if (!CloudFormatFromPath(entry.path().string(), &format, &ignored))
      continue;
    const bool excluded =
        std::any_of(exclude.begin(), exclude.end(), [&](const std::string& e) {
          std::error_code eq_ec;
          return !e.empty() && fs::equivalent(entry.path(), e, eq_ec);
        });
    if (!excluded) paths->push_back(entry.path().string());
  }
  if (ec) {
    *error = dir + ": " + ec.message();
    return false;
  }
  std::sort(paths->begin(),
            paths->end(),
            [](const std::string& a, const std::string& b) {
              return fs::path(a).filename() < fs::path(b).filename();
            });
  if (paths->empty()) {
    *error = dir + ": no point-cloud files (.pcd, .ply, .bin, .3d, .xyz, .txt)";
    return false;
  }
  return true;
}

// Reads KITTI poses (pose_io.h). With `calib_path`, the poses are KITTI
// camera (cam0) poses and are converted into the scanner frame with the Tr
// line (cam0_from_velo): V_i = Tr^-1 P_i Tr.
inline bool ReadSequencePoses(const std::string& poses_path,
                              const std::string& calib_path,
                              std::vector<Isometry3d>* poses,
                              std::string* error) {
  if (!ReadKittiPoses(poses_path, poses, error)) return false;
  if (calib_path.empty()) return true;
  Isometry3d cam0_from_velo;
  if (!ReadKittiCalibTr(calib_path, &cam0_from_velo, error)) return false;
  const Isometry3d velo_from_cam0 = cam0_from_velo.inverse();
  for (Isometry3d& pose : *poses) pose = velo_from_cam0 * pose * cam0_from_velo;
  return true;
}

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
