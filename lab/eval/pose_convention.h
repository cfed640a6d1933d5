#pragma once

// Which sensor convention a pose file's motion looks like. KITTI camera
// (cam0) poses move along their frame's z axis (the camera looks forward
// along z, y points down); Velodyne and most LiDAR poses move along x. A
// camera pose file read as LiDAR poses gives a plausible but wrong
// trajectory (errors of a metre per pair on KITTI), so the tools check the
// evidence and warn.

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

struct MotionAxes {
  // Sum over consecutive poses of |component| of the motion
  // pose_k^-1 * pose_{k+1}'s translation in pose k's frame [m].
  double x_m = 0.0;
  double y_m = 0.0;
  double z_m = 0.0;
  double total_m() const { return x_m + y_m + z_m; }
};

MotionAxes ComputeMotionAxes(const std::vector<Isometry3d>& poses);

// True when the motion is camera-like: at least 1 m of motion in all, and
// more than 70 % of it along z with less along x than along z. *evidence
// then says so with the numbers ("92 % of the 12.3 m of motion is along
// the poses' z axis ...").
bool LooksLikeCameraPoses(const std::vector<Isometry3d>& poses,
                          std::string* evidence);

}  // namespace mlndt
