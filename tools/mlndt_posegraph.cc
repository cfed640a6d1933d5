// mlndt_posegraph: every scan pose of a folder refined jointly in one
// ceres::Problem of ML-NDT pair residuals (the embedding API), from chained
// pairwise registrations or from an odometry, optionally with odometry
// factors of a stated noise and extra pairs (loop closures). The method is
// in lab/runs/pose_graph.h.
//
//   mlndt_posegraph --scans=DIR [--gt_poses=poses.txt] [--neighbors=2]
//                   [--odometry_poses=FILE [--odometry_noise_sigma_m=0.05
//                   --odometry_noise_sigma_deg=0.5] [--init=odometry]]
//                   [--pairs=i:j,...] [--information_scale=w]
//                   [--output_dir=DIR] [--output_json=FILE] [registration
//                   flags]
//
// The joint problem's flags are PoseGraphOptions' fields
// (tools/cli/pose_graph_flags.h).
//
// Writes trajectory_<init>.txt (chained or odometry) and trajectory_joint.txt
// (KITTI lines, world_from_scan, scan 0 = world) into --output_dir when
// given, and one JSON object to stdout (and --output_json). With --gt_poses
// (KITTI format, one line per scan in file-name order) the JSON has
//   ate_{<init>,joint}_m: RMSE of the translation error after aligning the
//       first poses (ComputeAte with FIRST_POSE, trajectory_metrics.h);
//   rpe_{<init>,joint}: mean relative pose error of consecutive scans
//       {"translation_m", "rotation_deg"}.

#include <gflags/gflags.h>

#include <iostream>
#include <string>
#include <vector>

#include "lab/eval/dataset.h"
#include "lab/runs/pose_graph.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/json_output.h"
#include "tools/cli/output_files.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/pose_graph_flags.h"
#include "tools/cli/posegraph_output.h"
#include "tools/cli/posegraph_pairs.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (files with a cloud extension, sorted by name)");
DEFINE_string(gt_poses, "", "Optional KITTI-format ground truth (world_from_scan, scan frame)");
DEFINE_string(pairs, "", "Extra pairs i:j,... (0-based, file-name order), e.g. loop closures");
DEFINE_string(odometry_poses, "",
              "KITTI-format odometry (world_from_scan per scan): a factor between consecutive "
              "scans with the noise below");
DEFINE_string(init, "chained", "Initial poses: chained (registrations) or odometry");
DEFINE_string(output_dir, "", "Folder for trajectory_<init>.txt and trajectory_joint.txt");
DEFINE_string(output_json, "", "Also write the JSON result to this file");
// clang-format on

namespace mlndt {
namespace {

int Fail(const std::string& message) {
  std::cerr << "mlndt_posegraph: " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << "mlndt_posegraph: " << message << std::endl;
  return tools::kExitUsage;
}

bool OptionsFromFlags(PoseGraphOptions* options, std::string* error) {
  if (FLAGS_init != "chained" && FLAGS_init != "odometry") {
    *error = "--init=" + FLAGS_init + ": chained or odometry";
    return false;
  }
  if (!tools::RegistrationOptionsFromFlags(&options->registration, error)) {
    *error += " (the joint problem is built from ML-NDT residuals)";
    return false;
  }
  if (!tools::ParseScanPairs(FLAGS_pairs, &options->extra_pairs, error)) {
    *error = "--pairs: " + *error;
    return false;
  }
  if (!tools::PoseGraphFlags().Apply(options, error)) return false;
  options->init_from_odometry = FLAGS_init == "odometry";
  return tools::CheckStartLayerBeforeMap(options->registration, error);
}

// A KITTI pose file with one pose per scan (CheckPoseCount).
bool ReadScanPoses(const std::string& flag,
                   const std::string& path,
                   size_t num_scans,
                   std::vector<Isometry3d>* poses,
                   std::string* error) {
  if (path.empty()) return true;
  if (!ReadSequencePoses(path, FLAGS_calib, poses, error)) {
    *error = flag + "=" + path + ": " + *error;
    return false;
  }
  return tools::CheckPoseCount(
      flag + "=" + path, poses->size(), num_scans, -1, error);
}

// Every check before any work: flags, outputs, scans and pose files.
bool PrepareRun(PoseGraphOptions* options,
                std::vector<std::string>* paths,
                std::vector<Isometry3d>* truth,
                std::string* error) {
  if (FLAGS_scans.empty()) return (*error = "--scans is required", false);
  if (!OptionsFromFlags(options, error) ||
      !tools::CheckOutputFile("output_json", FLAGS_output_json, error) ||
      !tools::CheckCameraPoseFlags(
          "--gt_poses", !FLAGS_gt_poses.empty(), error)) {
    return false;
  }
  if (!FLAGS_output_dir.empty() &&
      !tools::PrepareOutputDir(
          "output_dir",
          FLAGS_output_dir,
          {"trajectory_" + FLAGS_init + ".txt", "trajectory_joint.txt"},
          error)) {
    return false;
  }
  if (!ListScanFiles(FLAGS_scans,
                     {FLAGS_gt_poses, FLAGS_calib, FLAGS_odometry_poses},
                     paths,
                     error)) {
    return false;
  }
  if (paths->size() < 2)
    return (*error = FLAGS_scans + ": fewer than 2 scans", false);
  if (!ReadScanPoses(
          "--gt_poses", FLAGS_gt_poses, paths->size(), truth, error) ||
      !ReadScanPoses("--odometry_poses",
                     FLAGS_odometry_poses,
                     paths->size(),
                     &options->odometry,
                     error)) {
    return false;
  }
  if (!options->IsValid(paths->size(), error)) {
    *error = "flags: " + *error;
    return false;
  }
  return true;
}

int Run() {
  PoseGraphOptions options;
  std::vector<std::string> paths;
  std::vector<Isometry3d> truth;
  std::string error;
  if (!PrepareRun(&options, &paths, &truth, &error)) return Refuse(error);

  tools::ProgressPrinter progress("mlndt_posegraph joint");
  options.progress = &progress;
  PoseGraphSummary summary;
  const bool ok = RunPoseGraph(options, paths, &summary, &error);
  progress.Finish();
  if (!ok) return Fail(error);

  tools::Json json;
  if (!tools::PoseGraphJson(options, summary, truth, &json, &error) ||
      (!FLAGS_output_dir.empty() &&
       !tools::WritePoseGraphTrajectories(FLAGS_output_dir, summary, &error))) {
    return Fail(error);
  }
  std::cout << tools::JsonText(json);
  if (!FLAGS_output_json.empty() &&
      !tools::WriteJsonFile(FLAGS_output_json, json, &error)) {
    return Fail(error);
  }
  if (summary.chained_failures > 0) {
    return Fail(std::to_string(summary.chained_failures) +
                " chained registration(s) were not usable (they kept the "
                "previous relative pose): the trajectories are not to be "
                "used");
  }
  if (summary.check.verdict != "CONVERGENCE") {
    return Fail("the joint result is " + summary.check.verdict + ": " +
                summary.check.message +
                "; the joint trajectory is not to "
                "be used");
  }
  return tools::kExitOk;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Joint refinement of all scan poses from ML-NDT pairs (and an "
          "odometry).\n"
          "  mlndt_posegraph --scans=DIR [--gt_poses=FILE] [--neighbors=2] "
          "[--odometry_poses=FILE] [--pairs=i:j,...] [--output_dir=DIR]\n"
          "Exit 1 when a chained registration was not usable (LOW_QUALITY, "
          "DEGENERATE or FAILURE), or when the joint result's verdict is not "
          "CONVERGENCE (a pair or odometry factor that does not fit the "
          "joint poses: \"verdict\" in the JSON), after writing every "
          "file.",
          false,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
