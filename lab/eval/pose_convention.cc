#include "lab/eval/pose_convention.h"

#include <cmath>
#include <cstdio>

namespace mlndt {

MotionAxes ComputeMotionAxes(const std::vector<Isometry3d>& poses) {
  MotionAxes axes;
  for (size_t k = 0; k + 1 < poses.size(); ++k) {
    const Vector3d t = (poses[k].inverse() * poses[k + 1]).translation();
    axes.x_m += std::abs(t.x());
    axes.y_m += std::abs(t.y());
    axes.z_m += std::abs(t.z());
  }
  return axes;
}

bool LooksLikeCameraPoses(const std::vector<Isometry3d>& poses,
                          std::string* evidence) {
  const MotionAxes axes = ComputeMotionAxes(poses);
  const double total = axes.total_m();
  if (!(total >= 1.0) || !(axes.z_m > 0.7 * total)) return false;
  char text[256];
  std::snprintf(text,
                sizeof(text),
                "%.0f %% of the %.1f m of motion between consecutive poses "
                "is along the poses' z axis (x %.1f m, y %.1f m, z %.1f m), "
                "as for a forward-looking camera; LiDAR poses move along x",
                100.0 * axes.z_m / total,
                total,
                axes.x_m,
                axes.y_m,
                axes.z_m);
  *evidence = text;
  return true;
}

}  // namespace mlndt
