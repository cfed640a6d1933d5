#include "mlndt/grid/map_check.h"

#include <glog/logging.h>

#include <cmath>
#include <sstream>

#include "mlndt/common/rigid_transform.h"

namespace mlndt {

bool CheckMapUsable(const LayeredGrid& map, std::string* error) {
  CHECK(error != nullptr);
  if (map.num_layers() < 1) {
    *error = "the map has no layers";
    return false;
  }
  const Eigen::AlignedBox3d& bounds = map.bounds();
  if (!bounds.min().allFinite() || !bounds.max().allFinite() ||
      bounds.min().cwiseAbs().maxCoeff() > kMaxCoordinateM ||
      bounds.max().cwiseAbs().maxCoeff() > kMaxCoordinateM) {
    std::ostringstream message;
    message << "the map's bounding box (" << bounds.min().transpose() << ") - ("
            << bounds.max().transpose() << ") m is not finite or "
            << "beyond " << kMaxCoordinateM
            << " m: a point or pose holds an absurd number";
    *error = message.str();
    return false;
  }
  for (int i = 1; i <= map.num_layers(); ++i) {
    const NdtLayer& layer = map.layer(i);
    std::ostringstream message;
    message << "layer " << i << " of " << map.num_layers() << " (cell "
            << layer.cell_size() << " m)";
    if (!std::isfinite(layer.cell_size()) || !(layer.cell_size() > 0.0) ||
        layer.cell_size() > kMaxCoordinateM) {
      *error = "the map's " + message.str() + " has no usable cell edge";
      return false;
    }
    if (layer.cells().empty()) {
      *error = "the map has 0 occupied cells on its " + message.str() +
               ": too few points per cell (min_points_per_cell " +
               std::to_string(map.options().min_points_per_cell) +
               "); give more points or larger cells";
      return false;
    }
  }
  return true;
}

}  // namespace mlndt
