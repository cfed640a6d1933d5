#include "mlndt/cost/add_pair_residuals.h"

#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <glog/logging.h>

#include "mlndt/cost/internal/loss_for.h"
#include "mlndt/cost/mlndt_pair_cost.h"
#include "mlndt/cost/mlndt_pair_cost_analytic.h"
#include "mlndt/cost/mlndt_pair_factor.h"
#include "mlndt/cost/pair_residual_option_table.h"

namespace mlndt {
namespace {

void SetQuaternionManifoldUnlessSet(double* rotation, ceres::Problem* problem) {
  if (problem->GetManifold(rotation) == nullptr) {
    problem->SetManifold(rotation, new ceres::EigenQuaternionManifold);
  }
}

// The loss of every block of one call: the objective's, scaled by w unless
// w is 1 (nullptr when nothing will be added).
ceres::LossFunction* PairLoss(const PairResidualOptions& options,
                              const std::vector<Eigen::Vector3d>& points) {
  ceres::LossFunction* loss = internal::LossFor(options.objective, points);
  if (points.empty() || options.information_scale == 1.0) return loss;
  return new ceres::ScaledLoss(
      loss, options.information_scale, ceres::TAKE_OWNERSHIP);
}

// One block per point, all with one loss.
void AddPointBlocks(LayerSource layer,
                    const std::vector<Eigen::Vector3d>& points,
                    const PairResidualOptions& options,
                    double* rotation_i,
                    double* translation_i,
                    double* rotation_j,
                    double* translation_j,
                    ceres::Problem* problem,
                    std::vector<ceres::ResidualBlockId>* ids) {
  ceres::LossFunction* loss = PairLoss(options, points);
  const UnmatchedPolicy policy = options.objective.unmatched_policy;
  ids->reserve(points.size());
  for (const Eigen::Vector3d& point : points) {
    ceres::CostFunction* cost =
        options.analytic_jacobians
            ? static_cast<ceres::CostFunction*>(
                  new MlNdtPairCostAnalytic(layer, point, policy))
            : MlNdtPairCost::Create(layer, point, policy);
    ids->push_back(problem->AddResidualBlock(
        cost, loss, rotation_i, translation_i, rotation_j, translation_j));
  }
}

}  // namespace

bool PairResidualOptions::IsValid(std::string* error) const {
  if (!objective.IsValid(error)) {
    *error = "objective: " + *error;
    return false;
  }
  return PairResidualOptionsTable().Check(*this, error);
}

std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    LayerSource reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const PairResidualOptions& options,
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
  std::string error;
  CHECK(options.IsValid(&error)) << "AddMlNdtPairResiduals: " << error;
  if (input_points_of_scan_j.empty()) return {};
  std::vector<ceres::ResidualBlockId> ids;
  if (options.one_block_per_pair) {
    ids.push_back(problem->AddResidualBlock(
        new MlNdtPairFactor(reference_layer_of_scan_i,
                            input_points_of_scan_j,
                            options.objective,
                            options.information_scale),
        nullptr,
        world_from_scan_i_rotation,
        world_from_scan_i_translation,
        world_from_scan_j_rotation,
        world_from_scan_j_translation));
  } else {
    AddPointBlocks(reference_layer_of_scan_i,
                   input_points_of_scan_j,
                   options,
                   world_from_scan_i_rotation,
                   world_from_scan_i_translation,
                   world_from_scan_j_rotation,
                   world_from_scan_j_translation,
                   problem,
                   &ids);
  }
  SetQuaternionManifoldUnlessSet(world_from_scan_i_rotation, problem);
  SetQuaternionManifoldUnlessSet(world_from_scan_j_rotation, problem);
  return ids;
}

std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    LayerSource reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const ObjectiveOptions& objective,
    double* world_from_scan_i_rotation,
    double* world_from_scan_i_translation,
    double* world_from_scan_j_rotation,
    double* world_from_scan_j_translation,
    ceres::Problem* problem) {
  PairResidualOptions options;
  options.objective = objective;
  return AddMlNdtPairResiduals(reference_layer_of_scan_i,
                               input_points_of_scan_j,
                               options,
                               world_from_scan_i_rotation,
                               world_from_scan_i_translation,
                               world_from_scan_j_rotation,
                               world_from_scan_j_translation,
                               problem);
}

}  // namespace mlndt
