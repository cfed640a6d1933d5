#include "mlndt/cloud/point_cloud.h"

#include <algorithm>

namespace mlndt {

Eigen::AlignedBox3d BoundingBox(const PointCloud& cloud) {
  Eigen::AlignedBox3d box;  // Constructed empty.
  for (const Eigen::Vector3d& p : cloud.points()) box.extend(p);
  return box;
}

size_t RemoveNonFinite(PointCloud* cloud) {
  std::vector<Eigen::Vector3d>* points = cloud->mutable_points();
  const size_t before = points->size();
  points->erase(
      std::remove_if(points->begin(),
                     points->end(),
                     [](const Eigen::Vector3d& p) { return !p.allFinite(); }),
      points->end());
  return before - points->size();
}

bool AllFinite(const PointCloud& cloud) {
  return std::all_of(cloud.points().begin(),
                     cloud.points().end(),
                     [](const Eigen::Vector3d& p) { return p.allFinite(); });
}

PointCloud TransformCloud(const Eigen::Isometry3d& target_from_source,
                          const PointCloud& cloud) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(cloud.size());
  for (const Eigen::Vector3d& p : cloud.points())
    out.push_back(target_from_source * p);
  return PointCloud(std::move(out));
}

}  // namespace mlndt
