#pragma once

// Names the point that stretches a cloud's bounding box, for the messages
// of a cloud that needs too many map layers (a stray point at 1e30 m).

#include <Eigen/Core>
#include <string>
#include <vector>

namespace mlndt {
namespace internal {

// "the cloud spans <extent> m; its farthest point, index i, is at (x, y, z),
// r m from the origin: drop such points with a range filter" for the point
// of `points` farthest from the origin; "" for no points.
std::string DescribeFarthestPoint(const std::vector<Eigen::Vector3d>& points,
                                  double extent_m);

}  // namespace internal
}  // namespace mlndt
