#include "mlndt/odometry/deskew.h"

#include <cmath>

#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {

bool DeskewScan(const Vector6d& velocity,
                const std::vector<double>& point_times_s,
                PointCloud* cloud,
                std::string* error) {
  if (point_times_s.size() != cloud->size()) {
    *error = "deskew: " + std::to_string(point_times_s.size()) +
             " point times for " + std::to_string(cloud->size()) + " points";
    return false;
  }
  for (const double t : point_times_s) {
    if (!std::isfinite(t)) {
      *error = "deskew: a point time is not finite";
      return false;
    }
  }
  std::vector<Eigen::Vector3d>& points = *cloud->mutable_points();
  for (size_t i = 0; i < points.size(); ++i) {
    points[i] = TwistToMotion(velocity * point_times_s[i]) * points[i];
  }
  return true;
}

}  // namespace mlndt
