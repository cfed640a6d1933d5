#include "tools/cli/posegraph_metrics_json.h"

#include "lab/eval/posegraph_metrics.h"

namespace mlndt {
namespace tools {
namespace {

Json RpeJson(const PoseGraphAccuracy& accuracy) {
  return {{"translation_m", Number(accuracy.rpe_translation_m)},
          {"rotation_deg", Number(accuracy.rpe_rotation_deg)}};
}

}  // namespace

bool AddTrajectoryMetrics(const std::string& initial_name,
                          const std::vector<Isometry3d>& initial,
                          const std::vector<Isometry3d>& joint,
                          const std::vector<Isometry3d>& truth,
                          Json* json,
                          std::string* error) {
  PoseGraphAccuracy initial_accuracy, joint_accuracy;
  if (!EvaluatePoseGraphAccuracy(initial, truth, &initial_accuracy, error) ||
      !EvaluatePoseGraphAccuracy(joint, truth, &joint_accuracy, error)) {
    return false;
  }
  (*json)["ate_alignment"] = "first_pose";
  (*json)["ate_" + initial_name + "_m"] = Number(initial_accuracy.ate_m);
  (*json)["ate_joint_m"] = Number(joint_accuracy.ate_m);
  (*json)["rpe_" + initial_name] = RpeJson(initial_accuracy);
  (*json)["rpe_joint"] = RpeJson(joint_accuracy);
  return true;
}

}  // namespace tools
}  // namespace mlndt
