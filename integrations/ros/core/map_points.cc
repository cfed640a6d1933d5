#include "integrations/ros/core/map_points.h"

namespace mlndt {
namespace ros_core {

std::vector<Eigen::Vector3d> FinestCellMeans(const LayeredGrid& map) {
  std::vector<Eigen::Vector3d> points;
  if (map.empty()) return points;
  const NdtLayer& finest = map.layer(map.num_layers());
  points.reserve(finest.cells().size());
  for (const NdtCell& cell : finest.cells()) points.push_back(cell.mean);
  return points;
}

}  // namespace ros_core
}  // namespace mlndt
