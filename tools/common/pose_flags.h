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

}  // namespace tools
}  // namespace mlndt
