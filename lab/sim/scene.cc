#include "lab/sim/scene.h"

#include <glog/logging.h>

#include <algorithm>

namespace mlndt {
namespace sim {

double ScenePath::Length() const {
  double length = 0.0;
  for (size_t k = 1; k < points.size(); ++k) {
    length += (points[k] - points[k - 1]).norm();
  }
  return length;
}

Eigen::Vector3d ScenePath::PointAt(double s) const {
  CHECK_GE(points.size(), 2u);
  s = std::max(0.0, s);
  for (size_t k = 1; k < points.size(); ++k) {
    const double segment = (points[k] - points[k - 1]).norm();
    if (s <= segment || k + 1 == points.size()) {
      const double f = segment > 0.0 ? std::min(1.0, s / segment) : 0.0;
      return points[k - 1] + f * (points[k] - points[k - 1]);
    }
    s -= segment;
  }
  return points.back();
}

Eigen::Vector3d ScenePath::TangentAt(double s) const {
  CHECK_GE(points.size(), 2u);
  s = std::max(0.0, s);
  for (size_t k = 1; k < points.size(); ++k) {
    const double segment = (points[k] - points[k - 1]).norm();
    if (s < segment || k + 1 == points.size()) {
      return (points[k] - points[k - 1]).normalized();
    }
    s -= segment;
  }
  return (points.back() - points[points.size() - 2]).normalized();
}

}  // namespace sim
}  // namespace mlndt
