#pragma once

// KITTI camera poses on the command line, one way in every tool that reads
// pose files (--poses, --gt_poses, --initial_poses): the two shared flags
// defined in pose_flags.cc:
//
//   --poses_are_camera   the pose files hold KITTI camera (cam0) poses, as
//                        KITTI's poses/XX.txt do; refused without --calib
//   --calib=calib.txt    the KITTI calibration whose Tr line converts them
//                        into the scans' (Velodyne) frame: V = Tr^-1 P Tr;
//                        refused without --poses_are_camera
//
// Nothing is converted on a guess from a file's name or contents: a camera
// pose file read as Velodyne poses gives a wrong, plausible trajectory, so
// the user says which it is. mlndt_sequence warns (with the evidence) when
// --gt_poses moves along z as camera poses do (lab/eval/pose_convention.h).

#include <gflags/gflags.h>

#include <cstddef>
#include <string>

DECLARE_string(calib);
DECLARE_bool(poses_are_camera);

namespace mlndt {
namespace tools {

// Refuses --poses_are_camera without --calib, --calib without
// --poses_are_camera, and both when no pose file is given
// (`any_pose_file`); `pose_flags` ("--poses", ...) name the tool's pose
// flags in the messages.
bool CheckCameraPoseFlags(const std::string& pose_flags,
                          bool any_pose_file,
                          std::string* error);

// Pose k belongs to scan k: refuses the pose file `given` ("--poses=FILE")
// with fewer poses than the `num_scans` scans, and with more unless
// --max_scans (`max_scans` > 0) took the first scans of a longer run; a
// missing scan or a wrong file would shift every later pose by one.
// `max_scans` < 0: the tool has no --max_scans.
bool CheckPoseCount(const std::string& given,
                    size_t num_poses,
                    size_t num_scans,
                    int max_scans,
                    std::string* error);

}  // namespace tools
}  // namespace mlndt
