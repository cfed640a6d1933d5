#pragma once

// A layered map drawn as points: the means of its finest layer's cells (Eq.
// 2), one point per occupied cell, in the map's frame. What the nodes
// publish as the local map (odometry) and the map (localiser): the map as
// the registration sees it, a few thousand points instead of the scans'.

#include <vector>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace ros_core {

std::vector<Eigen::Vector3d> FinestCellMeans(const LayeredGrid& map);

}  // namespace ros_core
}  // namespace mlndt
