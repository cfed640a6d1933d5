#include "mlndt/odometry/deskew.h"

#include <cmath>

#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {

bool DeskewScan(const Vector6d& velocity,
                const std::vector<double>& point_times_s,
                PointCloud* cloud,
                std::string* error,
                size_t* removed) {
  if (point_times_s.size() != cloud->size()) {
    *error = "deskew: " + std::to_string(point_times_s.size()) +
             " point times for " + std::to_string(cloud->size()) + " points";
    return false;
  }
  std::vector<Eigen::Vector3d>& points = *cloud->mutable_points();
  size_t kept = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(point_times_s[i])) continue;
    points[kept++] = TwistToMotion(velocity * point_times_s[i]) * points[i];
  }
  if (removed != nullptr) *removed = points.size() - kept;
  points.resize(kept);
  return true;
}

}  // namespace mlndt
