#include "mlndt/common/internal/farthest_point.h"

#include <sstream>

namespace mlndt {
namespace internal {

std::string DescribeFarthestPoint(const std::vector<Eigen::Vector3d>& points,
                                  double extent_m) {
  if (points.empty()) return "";
  size_t far = 0;
  for (size_t i = 1; i < points.size(); ++i) {
    if (points[i].squaredNorm() > points[far].squaredNorm()) far = i;
  }
  const Eigen::Vector3d& p = points[far];
  std::ostringstream out;
  out << "the cloud spans " << extent_m << " m; its farthest point, index "
      << far << ", is at (" << p.x() << ", " << p.y() << ", " << p.z() << "), "
      << p.norm() << " m from the origin: drop such points with a range filter";
  return out.str();
}

}  // namespace internal
}  // namespace mlndt
