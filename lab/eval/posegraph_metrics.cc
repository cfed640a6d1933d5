#include "lab/eval/posegraph_metrics.h"

#include "lab/eval/trajectory_metrics.h"

namespace mlndt {

bool EvaluatePoseGraphAccuracy(const std::vector<Isometry3d>& estimate,
                               const std::vector<Isometry3d>& truth,
                               PoseGraphAccuracy* accuracy,
                               std::string* error) {
  AteOptions ate_options;
  ate_options.alignment = TrajectoryAlignment::FIRST_POSE;
  AteSummary ate;
  RpeSummary rpe;
  if (!ComputeAte(ate_options, truth, estimate, &ate, error) ||
      !ComputeRpe(RpeOptions(), truth, estimate, &rpe, error)) {
    return false;
  }
  accuracy->ate_m = ate.rmse_m;
  accuracy->rpe_translation_m = rpe.translation_m.mean;
  accuracy->rpe_rotation_deg = rpe.rotation_deg.mean;
  return true;
}

}  // namespace mlndt
