#include "mlndt/cost/add_pair_residuals.h"

#include <ceres/manifold.h>
#include <glog/logging.h>

#include "mlndt/cost/internal/loss_for.h"
#include "mlndt/cost/mlndt_pair_cost.h"

namespace mlndt {
namespace {

void SetQuaternionManifoldUnlessSet(double* rotation, ceres::Problem* problem) {
  if (problem->GetManifold(rotation) == nullptr) {
    problem->SetManifold(rotation, new ceres::EigenQuaternionManifold);
  }
}

}  // namespace

std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    const NdtLayer& reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const ObjectiveOptions& objective,
    double* world_from_scan_i_rotation,
    double* world_from_scan_i_translation,
    double* world_from_scan_j_rotation,
    double* world_from_scan_j_translation,
    ceres::Problem* problem) {
  CHECK(problem != nullptr);
  CHECK(world_from_scan_i_rotation != nullptr);
  CHECK(world_from_scan_i_translation != nullptr);
  CHECK(world_from_scan_j_rotation != nullptr);
  CHECK(world_from_scan_j_translation != nullptr);
  CHECK(world_from_scan_i_rotation != world_from_scan_j_rotation &&
        world_from_scan_i_translation != world_from_scan_j_translation)
      << "AddMlNdtPairResiduals: scan i and scan j need their own pose blocks";
  ceres::LossFunction* loss =
      internal::LossFor(objective, input_points_of_scan_j);
  std::vector<ceres::ResidualBlockId> ids;
  ids.reserve(input_points_of_scan_j.size());
  for (const Eigen::Vector3d& point : input_points_of_scan_j) {
    ids.push_back(problem->AddResidualBlock(
        MlNdtPairCost::Create(
            reference_layer_of_scan_i, point, objective.unmatched_policy),
        loss,
        world_from_scan_i_rotation,
        world_from_scan_i_translation,
        world_from_scan_j_rotation,
        world_from_scan_j_translation));
  }
  if (!input_points_of_scan_j.empty()) {
    SetQuaternionManifoldUnlessSet(world_from_scan_i_rotation, problem);
    SetQuaternionManifoldUnlessSet(world_from_scan_j_rotation, problem);
  }
  return ids;
}

}  // namespace mlndt
