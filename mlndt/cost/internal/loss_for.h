#pragma once

// The loss function a call of the embedding API puts on its blocks.

#include <ceres/loss_function.h>

#include <Eigen/Core>
#include <vector>

#include "mlndt/cost/objective_options.h"

namespace mlndt {
namespace internal {

// A new loss for `objective` (nullptr for NONE, and when nothing will be
// added, so that no loss is left without an owner).
inline ceres::LossFunction* LossFor(
    const ObjectiveOptions& objective,
    const std::vector<Eigen::Vector3d>& points) {
  return points.empty() ? nullptr
                        : CreateLoss(objective.loss, objective.loss_scale);
}

}  // namespace internal
}  // namespace mlndt
