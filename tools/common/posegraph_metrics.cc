#include "tools/common/posegraph_metrics.h"

#include "lab/eval/trajectory_metrics.h"

namespace mlndt {
namespace tools {
namespace {

struct Metrics {
  double ate_m = 0.0;
  double rpe_translation_m = 0.0;
  double rpe_rotation_deg = 0.0;
};

// ATE after aligning the first poses, and the mean RPE of consecutive scans
// (lab/eval/trajectory_metrics.h).
bool Evaluate(const std::vector<Isometry3d>& estimate,
              const std::vector<Isometry3d>& truth,
              Metrics* metrics,
              std::string* error) {
  AteOptions ate_options;
  ate_options.alignment = TrajectoryAlignment::FIRST_POSE;
  AteSummary ate;
  RpeSummary rpe;
  if (!ComputeAte(ate_options, truth, estimate, &ate, error) ||
      !ComputeRpe(RpeOptions(), truth, estimate, &rpe, error)) {
    return false;
  }
  metrics->ate_m = ate.rmse_m;
  metrics->rpe_translation_m = rpe.translation_m.mean;
  metrics->rpe_rotation_deg = rpe.rotation_deg.mean;
  return true;
}

Json RpeJson(const Metrics& metrics) {
  return {{"translation_m", Number(metrics.rpe_translation_m)},
          {"rotation_deg", Number(metrics.rpe_rotation_deg)}};
}

}  // namespace

bool AddTrajectoryMetrics(const std::string& initial_name,
                          const std::vector<Isometry3d>& initial,
                          const std::vector<Isometry3d>& joint,
                          const std::vector<Isometry3d>& truth,
                          Json* json,
                          std::string* error) {
  Metrics initial_metrics, joint_metrics;
  if (!Evaluate(initial, truth, &initial_metrics, error) ||
      !Evaluate(joint, truth, &joint_metrics, error)) {
    return false;
  }
  (*json)["ate_alignment"] = "first_pose";
  (*json)["ate_" + initial_name + "_m"] = Number(initial_metrics.ate_m);
  (*json)["ate_joint_m"] = Number(joint_metrics.ate_m);
  (*json)["rpe_" + initial_name] = RpeJson(initial_metrics);
  (*json)["rpe_joint"] = RpeJson(joint_metrics);
  return true;
}

}  // namespace tools
}  // namespace mlndt
