#include "lab/runs/scan_store.h"

#include <glog/logging.h>

#include <algorithm>
#include <filesystem>

#include "mlndt/cloud/io.h"
#include "mlndt/common/timer.h"

namespace mlndt {

ScanStore::ScanStore(std::vector<std::string> paths)
    : paths_(std::move(paths)), clouds_(paths_.size()), maps_(paths_.size()) {}

ScanStore::ScanStore(std::vector<std::string> names, ScanLoader load)
    : paths_(std::move(names)),
      load_(std::move(load)),
      clouds_(paths_.size()),
      maps_(paths_.size()) {}

std::string ScanStore::file_name(size_t i) const {
  return std::filesystem::path(paths_.at(i)).filename().string();
}

const PointCloud* ScanStore::Cloud(size_t i, std::string* error) {
  CHECK(error != nullptr);
  if (clouds_.at(i) == nullptr) {
    auto cloud = std::make_unique<PointCloud>();
    const bool read =
        load_ ? load_(i, cloud.get(), error)
              : ReadPointCloud(paths_[i], cloud.get(), nullptr, error);
    if (!read) return nullptr;
    if (cloud->size() == 0) {
      *error = paths_[i] + ": no finite points";
      return nullptr;
    }
    clouds_[i] = std::move(cloud);
  }
  return clouds_[i].get();
}

const LayeredGrid* ScanStore::Map(size_t i,
                                  const LayeredGridOptions& options,
                                  int num_threads,
                                  double* build_time_s,
                                  std::string* error) {
  CHECK(build_time_s != nullptr);
  CHECK(error != nullptr);
  *build_time_s = 0.0;
  std::vector<CachedMap>& cached = maps_.at(i);
  const auto found =
      std::find_if(cached.begin(), cached.end(), [&](const CachedMap& entry) {
        return entry.first == options;
      });
  if (found != cached.end()) return found->second.get();

  const PointCloud* cloud = Cloud(i, error);
  if (cloud == nullptr) return nullptr;
  const double start = NowSeconds();
  auto grid = std::make_unique<LayeredGrid>();
  if (!LayeredGrid::Build(options, *cloud, num_threads, grid.get(), error)) {
    *error = paths_[i] + ": map: " + *error;
    return nullptr;
  }
  *build_time_s = NowSeconds() - start;
  ++num_maps_built_;
  cached.emplace_back(options, std::move(grid));
  return cached.back().second.get();
}

void ScanStore::ReleaseBefore(size_t first) {
  for (size_t i = 0; i < std::min(first, paths_.size()); ++i) {
    clouds_[i].reset();
    maps_[i].clear();
  }
}

}  // namespace mlndt
