#include "tools/cli/posegraph_output.h"

#include <filesystem>

#include "lab/eval/posegraph_metrics.h"
#include "mlndt/cloud/pose_io.h"

namespace mlndt {
namespace tools {
namespace {

// "chained" or "odometry": how the initial poses were found.
std::string InitialName(const PoseGraphSummary& summary) {
  return summary.initial_is_chained ? "chained" : "odometry";
}

// The mean RPE of consecutive scans as JSON.
Json RpeJson(const PoseGraphAccuracy& accuracy) {
  return {{"translation_m", Number(accuracy.rpe_translation_m)},
          {"rotation_deg", Number(accuracy.rpe_rotation_deg)}};
}

// Adds ate_alignment, ate_{initial,joint}_m and rpe_{initial,joint}
// ({"translation_m", "rotation_deg"}) to *json, `initial_name` naming the
// initial trajectory ("chained" or "odometry"): the ATE after aligning the
// first poses and the mean RPE of consecutive scans
// (EvaluatePoseGraphAccuracy, lab/eval/posegraph_metrics.h); false with
// *error when a trajectory does not match the truth.
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

}  // namespace

bool WritePoseGraphTrajectories(const std::string& dir,
                                const PoseGraphSummary& summary,
                                std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = dir + ": " + ec.message();
    return false;
  }
  const std::string initial =
      dir + "/trajectory_" + InitialName(summary) + ".txt";
  return WriteKittiPoses(initial, summary.initial, error) &&
         WriteKittiPoses(dir + "/trajectory_joint.txt", summary.joint, error);
}

namespace {

// The verdict on the joint poses (pose_graph_check.h).
void AddJointCheck(const PoseGraphCheck& check, Json* json) {
  (*json)["verdict"] = check.verdict;
  if (!check.message.empty()) (*json)["verdict_message"] = check.message;
  Json pairs = Json::array();
  for (const PoseGraphPairCheck& c : check.pairs) {
    pairs.push_back({{"pair", {c.map_scan, c.point_scan}},
                     {"termination", c.termination},
                     {"nees", Number(c.nees)},
                     {"translation_m", Number(c.translation_m)},
                     {"rotation_deg", Number(c.rotation_deg)}});
  }
  (*json)["pair_checks"] = std::move(pairs);
  if (!check.odometry_chi2.empty()) {
    Json chi2 = Json::array();
    for (double value : check.odometry_chi2) chi2.push_back(Number(value));
    (*json)["odometry_chi2"] = std::move(chi2);
  }
}

}  // namespace

bool PoseGraphJson(const PoseGraphOptions& options,
                   const PoseGraphSummary& summary,
                   const std::vector<Isometry3d>& truth,
                   Json* json_out,
                   std::string* error) {
  Json json = ToolJson("mlndt_posegraph");
  json["scans"] = summary.joint.size();
  json["init"] = InitialName(summary);
  json["neighbors"] = options.neighbors;
  json["extra_pairs"] = options.extra_pairs.size();
  json["joint_layers"] = options.joint_layers;
  json["joint_both_directions"] = options.both_directions;
  json["joint_point_blocks"] = options.point_blocks;
  json["information_scale"] = Number(options.information_scale);
  json["directed_pairs"] = summary.directed_pairs;
  json["odometry_factors"] = summary.odometry_factors;
  if (summary.odometry_factors > 0) {
    json["odometry_sigma_m"] = Number(options.odometry_noise.sigma_m);
    json["odometry_sigma_deg"] = Number(options.odometry_noise.sigma_deg);
  }
  json["residual_blocks"] = summary.residual_blocks;
  json["linear_solver"] = summary.linear_solver;
  json["chained_failures"] = summary.chained_failures;
  json["joint_iterations"] = summary.iterations;
  json["joint_termination"] = summary.termination;
  json["joint_initial_cost"] = Number(summary.initial_cost);
  json["joint_cost_at_" + InitialName(summary)] =
      Number(summary.cost_at_initial);
  json["joint_final_cost"] = Number(summary.final_cost);
  AddJointCheck(summary.check, &json);
  if (!truth.empty() && !AddTrajectoryMetrics(InitialName(summary),
                                              summary.initial,
                                              summary.joint,
                                              truth,
                                              &json,
                                              error)) {
    return false;
  }
  json["time_ms"] = {{"total", summary.total_s * 1e3},
                     {"maps", summary.maps_s * 1e3},
                     {"chained", summary.chained_s * 1e3},
                     {"joint", summary.joint_s * 1e3}};
  *json_out = std::move(json);
  return true;
}

}  // namespace tools
}  // namespace mlndt
