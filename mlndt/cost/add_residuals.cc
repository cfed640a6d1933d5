#include "mlndt/cost/add_residuals.h"

#include <ceres/manifold.h>
#include <glog/logging.h>

#include "mlndt/cost/mlndt_point_cost.h"

namespace mlndt {

std::vector<ceres::ResidualBlockId> AddMlNdtResiduals(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ResidualOptions& options,
    double* reference_from_input_xi,
    ceres::Problem* problem) {
  CHECK(problem != nullptr);
  CHECK(reference_from_input_xi != nullptr);
  std::vector<ceres::ResidualBlockId> ids;
  ids.reserve(input_points.size());
  for (const Eigen::Vector3d& point : input_points) {
    ids.push_back(problem->AddResidualBlock(
        MlNdtPointCost::Create(
            reference_layer, point, options.unmatched_policy),
        options.loss_function,
        reference_from_input_xi));
  }
  return ids;
}

std::vector<ceres::ResidualBlockId> AddMlNdtResidualsQuaternion(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ResidualOptions& options,
    double* reference_from_input_rotation,
    double* reference_from_input_translation,
    ceres::Problem* problem) {
  CHECK(problem != nullptr);
  CHECK(reference_from_input_rotation != nullptr);
  CHECK(reference_from_input_translation != nullptr);
  std::vector<ceres::ResidualBlockId> ids;
  ids.reserve(input_points.size());
  for (const Eigen::Vector3d& point : input_points) {
    ids.push_back(problem->AddResidualBlock(
        MlNdtPointCostQuaternion::Create(
            reference_layer, point, options.unmatched_policy),
        options.loss_function,
        reference_from_input_rotation,
        reference_from_input_translation));
  }
  if (!input_points.empty() &&
      problem->GetManifold(reference_from_input_rotation) == nullptr) {
    problem->SetManifold(reference_from_input_rotation,
                         new ceres::EigenQuaternionManifold);
  }
  return ids;
}

}  // namespace mlndt
