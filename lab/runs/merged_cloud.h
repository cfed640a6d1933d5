#pragma once

// One cloud of a whole scan folder: every scan moved into the first scan's
// frame with its ground-truth pose (first_from_scan = P_0^-1 P_i) and
// appended in scan order, as mlndt_scaling subsamples it.

#include <string>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

// The scans of `scans_dir` (ListScanFiles, sorted by name; the pose and
// calib files left out) with `poses_path`'s KITTI world_from_scan lines
// (camera poses converted with `calib` when given, ReadSequencePoses).
// False with *error when a file cannot be read or there are fewer poses
// than scans.
bool MergeScansInFirstFrame(const std::string& scans_dir,
                            const std::string& poses_path,
                            const std::string& calib,
                            PointCloud* merged,
                            size_t* num_scans,
                            std::string* error);

}  // namespace mlndt
