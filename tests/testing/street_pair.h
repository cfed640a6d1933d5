#pragma once

// The synthetic street scene as the hand-written backends' tests use it: a
// default map of one sampling (20,000 points) and a second sampling (3,000
// points) moved by a small pose (0.4, -0.3, 0.1 m; 2 deg of yaw).

#include <Eigen/Core>
#include <vector>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace testing {

struct StreetPair {
  LayeredGrid map;
  std::vector<Eigen::Vector3d> input;
};

// Built once per test binary.
const StreetPair& Street();

}  // namespace testing
}  // namespace mlndt
