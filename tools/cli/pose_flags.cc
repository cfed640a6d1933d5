#include "tools/cli/pose_flags.h"

// clang-format off
DEFINE_string(calib, "",
              "KITTI calib.txt whose Tr line converts camera (cam0) poses into the scans' "
              "(Velodyne) frame, V = Tr^-1 P Tr; needs --poses_are_camera");
DEFINE_bool(poses_are_camera, false,
            "The pose files hold KITTI camera (cam0) poses (KITTI's poses/XX.txt); needs "
            "--calib");
// clang-format on

namespace mlndt {
namespace tools {

bool CheckCameraPoseFlags(const std::string& pose_flags,
                          bool any_pose_file,
                          std::string* error) {
  if (FLAGS_poses_are_camera && FLAGS_calib.empty()) {
    *error =
        "--poses_are_camera needs --calib=calib.txt (KITTI's Tr line converts "
        "camera poses into the scans' frame)";
    return false;
  }
  if (!FLAGS_calib.empty() && !FLAGS_poses_are_camera) {
    *error =
        "--calib converts camera poses: give --poses_are_camera with it (or "
        "leave --calib out for poses in the scans' frame)";
    return false;
  }
  if (!FLAGS_calib.empty() && !any_pose_file) {
    *error = "--calib converts pose files; give it with " + pose_flags;
    return false;
  }
  return true;
}

bool CheckPoseCount(const std::string& given,
                    size_t num_poses,
                    size_t num_scans,
                    int max_scans,
                    std::string* error) {
  if (num_poses == num_scans || (num_poses > num_scans && max_scans > 0)) {
    return true;
  }
  *error = given + " has " + std::to_string(num_poses) + " poses for " +
           std::to_string(num_scans) + " scans (pose k belongs to scan k" +
           (max_scans == 0 ? "; use --max_scans to take the first scans of a "
                             "longer run)"
                           : ")");
  return false;
}

}  // namespace tools
}  // namespace mlndt
