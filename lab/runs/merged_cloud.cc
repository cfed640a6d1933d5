#include "lab/runs/merged_cloud.h"

#include <vector>

#include "lab/eval/dataset.h"
#include "lab/runs/scan_store.h"

namespace mlndt {

bool MergeScansInFirstFrame(const std::string& scans_dir,
                            const std::string& poses_path,
                            const std::string& calib,
                            PointCloud* merged,
                            size_t* num_scans,
                            std::string* error) {
  std::vector<std::string> paths;
  if (!ListScanFiles(scans_dir, {poses_path, calib}, &paths, error)) {
    return false;
  }
  std::vector<Isometry3d> world_from_scan;
  if (!ReadSequencePoses(poses_path, calib, &world_from_scan, error)) {
    return false;
  }
  if (world_from_scan.size() < paths.size()) {
    *error = poses_path + " has " + std::to_string(world_from_scan.size()) +
             " poses for " + std::to_string(paths.size()) + " scans in " +
             scans_dir;
    return false;
  }
  ScanStore store(paths);
  const Isometry3d first_from_world = world_from_scan[0].inverse();
  for (size_t i = 0; i < paths.size(); ++i) {
    const PointCloud* cloud = store.Cloud(i, error);
    if (cloud == nullptr) return false;
    const Isometry3d first_from_scan = first_from_world * world_from_scan[i];
    merged->Reserve(merged->size() + cloud->size());
    for (const Eigen::Vector3d& p : cloud->points()) {
      merged->Add(first_from_scan * p);
    }
    store.ReleaseBefore(i + 1);
  }
  *num_scans = paths.size();
  return true;
}

}  // namespace mlndt
