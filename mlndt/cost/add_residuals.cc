#include "mlndt/cost/add_residuals.h"

#include <ceres/manifold.h>
#include <glog/logging.h>

#include "mlndt/cost/internal/loss_for.h"
#include "mlndt/cost/mlndt_point_cost.h"

namespace mlndt {

std::vector<ceres::ResidualBlockId> AddMlNdtResiduals(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    double* reference_from_input_xi,
    ceres::Problem* problem) {
  CHECK(problem != nullptr);
  CHECK(reference_from_input_xi != nullptr);
  ceres::LossFunction* loss = internal::LossFor(objective, input_points);
  std::vector<ceres::ResidualBlockId> ids;
  ids.reserve(input_points.size());
  for (const Eigen::Vector3d& point : input_points) {
    ids.push_back(problem->AddResidualBlock(
        MlNdtPointCost::Create(
            reference_layer, point, objective.unmatched_policy),
        loss,
        reference_from_input_xi));
  }
  return ids;
}

std::vector<ceres::ResidualBlockId> AddMlNdtResidualsQuaternion(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    double* reference_from_input_rotation,
    double* reference_from_input_translation,
    ceres::Problem* problem) {
  CHECK(problem != nullptr);
  CHECK(reference_from_input_rotation != nullptr);
  CHECK(reference_from_input_translation != nullptr);
  ceres::LossFunction* loss = internal::LossFor(objective, input_points);
  std::vector<ceres::ResidualBlockId> ids;
  ids.reserve(input_points.size());
  for (const Eigen::Vector3d& point : input_points) {
    ids.push_back(problem->AddResidualBlock(
        MlNdtPointCostQuaternion::Create(
            reference_layer, point, objective.unmatched_policy),
        loss,
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
