#pragma once

// The bundled koide3 pair as solver tests use it: the default map of the
// first scan and the default GBS samples of the second (about 0.5 m apart).

#include <Eigen/Core>
#include <vector>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {
namespace testing {

struct Koide3MapAndSamples {
  LayeredGrid map;
  std::vector<Eigen::Vector3d> samples;
};

// Built once per test binary.
const Koide3MapAndSamples& Koide3Pair();

}  // namespace testing
}  // namespace mlndt
