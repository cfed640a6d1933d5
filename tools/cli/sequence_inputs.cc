#include "tools/cli/sequence_inputs.h"

#include <algorithm>
#include <iostream>

#include "lab/eval/dataset.h"
#include "lab/eval/pose_convention.h"
#include "tools/cli/adaptive_start_layer_flags.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/pose_flags.h"

namespace mlndt {
namespace tools {

namespace {

// `source` names the scans (the folder or the bag) in the too-few-scans
// message; `gt_poses` may be empty. Warns on stderr when the ground truth
// looks like KITTI camera poses read without --poses_are_camera. False with
// *error (naming the flag or file) on too few scans for the step, poses
// that cannot be read or whose count is not the scans' (CheckPoseCount;
// `max_scans` is --max_scans), or gt_fraction without ground truth.
bool ReadSequenceRunPoses(const SequenceOptions& options,
                          const std::string& source,
                          size_t num_scans,
                          int max_scans,
                          const std::string& gt_poses,
                          std::vector<Isometry3d>* truth,
                          std::vector<Isometry3d>* odometry,
                          std::string* error) {
  const std::string scans = std::to_string(num_scans) + " scans";
  if (num_scans <= options.step) {
    *error = source + ": " + scans +
             ", too few for --step=" + std::to_string(options.step);
    return false;
  }
  if (!gt_poses.empty() &&
      !ReadSequencePoses(gt_poses, FLAGS_calib, truth, error)) {
    return false;
  }
  std::string evidence;
  if (!FLAGS_poses_are_camera && LooksLikeCameraPoses(*truth, &evidence)) {
    std::cerr << "mlndt_sequence: WARNING: --gt_poses=" << gt_poses
              << " looks like KITTI camera (cam0) poses read as the scans' "
                 "own: "
              << evidence
              << ". If it is KITTI's poses/XX.txt, add --poses_are_camera "
                 "--calib=calib.txt; else every error below is measured "
                 "against the wrong frame.\n";
  }
  if (!gt_poses.empty() && !CheckPoseCount("--gt_poses=" + gt_poses,
                                           truth->size(),
                                           num_scans,
                                           max_scans,
                                           error)) {
    return false;
  }
  if (options.init.mode == InitMode::GT_FRACTION && truth->empty()) {
    *error = "--init=gt_fraction:c needs --gt_poses";
    return false;
  }
  if (options.init.mode != InitMode::POSES) return true;
  if (!ReadSequencePoses(
          options.init.poses_path, FLAGS_calib, odometry, error)) {
    return false;
  }
  return CheckPoseCount("--init=poses:" + options.init.poses_path,
                        odometry->size(),
                        num_scans,
                        max_scans,
                        error);
}

}  // namespace

bool AdaptiveOptionsFromFlags(AdaptiveStartLayerOptions* adaptive,
                              std::string* error) {
  if (!AdaptiveStartLayerFlags().Apply(adaptive, error)) return false;
  const std::vector<double>& rates = adaptive->fail_rate_thresholds;
  if (!std::is_sorted(rates.begin(), rates.end())) {
    const std::string flag = "adaptive_fail_rate_thresholds";
    *error = GivenFlagName(flag) + "=" + FlagText(flag) +
             ": expected ascending numbers in [0, 1], e.g. 0.05,0.2";
    return false;
  }
  return true;
}

bool ReadSequenceInputs(const SequenceOptions& options,
                        const std::string& scans_dir,
                        const std::string& gt_poses,
                        int max_scans,
                        ScanInput* input,
                        std::vector<Isometry3d>* truth,
                        std::vector<Isometry3d>* odometry,
                        std::string* error) {
  if (!ScanInputFromScansFlag(
          scans_dir,
          {gt_poses, FLAGS_calib, options.init.poses_path, FLAGS_times},
          static_cast<size_t>(max_scans),
          input,
          error) ||
      !input->ReadBagStamps(error)) {
    return false;
  }
  return ReadSequenceRunPoses(options,
                              FLAGS_bag.empty() ? scans_dir : FLAGS_bag,
                              input->size(),
                              max_scans,
                              gt_poses,
                              truth,
                              odometry,
                              error);
}

}  // namespace tools
}  // namespace mlndt
