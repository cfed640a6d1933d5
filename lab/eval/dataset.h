#pragma once

// The scans and poses of a sequence folder: listing the scan files, and
// reading ground-truth poses in the scanner frame (KITTI poses are camera
// poses).

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

// Lists the regular files directly in `dir` whose extension is a cloud
// format (cloud_format.h), sorted by file name. Files that are the same as a
// path in `exclude` (pose or calibration files kept beside the scans; .txt
// is also a cloud extension) are left out; empty entries are ignored. A
// .txt file is a scan only in a folder with no other cloud file, and only
// when its first line holds a point ("x y z"): stamps.txt, calib.txt,
// poses and trajectories beside .pcd or .bin scans are left out. False
// with *error when the folder cannot be read or holds no scans.
bool ListScanFiles(const std::string& dir,
                   const std::vector<std::string>& exclude,
                   std::vector<std::string>* paths,
                   std::string* error);

// KITTI camera (cam0) poses P_i into the Velodyne frame:
// V_i = Tr^-1 P_i Tr with Tr = cam0_from_velo (the calib.txt Tr line), so
// that V_i maps Velodyne points of frame i into the Velodyne frame of
// frame 0 when P_0 is the identity.
std::vector<Isometry3d> CameraToVelodynePoses(
    const std::vector<Isometry3d>& cam0_poses,
    const Isometry3d& cam0_from_velo);

// Reads KITTI poses (pose_io.h). With a `calib_path`, they are KITTI camera
// (cam0) poses and are converted with its Tr line (CameraToVelodynePoses);
// with an empty one they are used as they are.
bool ReadSequencePoses(const std::string& poses_path,
                       const std::string& calib_path,
                       std::vector<Isometry3d>* poses,
                       std::string* error);

}  // namespace mlndt
