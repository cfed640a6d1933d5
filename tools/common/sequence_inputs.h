#pragma once

// mlndt_sequence's poses: the ground truth (--gt_poses) and the odometry of
// --init=poses:FILE, one pose per scan, checked against the scans before
// any pair is registered.

#include <string>
#include <vector>

#include "lab/runs/sequence_registration.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace tools {

// `source` names the scans (the folder or the bag) in the too-few-scans
// message; `gt_poses` may be empty. Warns on stderr when the ground truth
// looks like KITTI camera poses read without --poses_are_camera. False with
// *error (naming the flag or file) on too few scans for the step, poses
// that cannot be read or are fewer than the scans, or gt_fraction without
// ground truth.
bool ReadSequenceRunPoses(const SequenceOptions& options,
                          const std::string& source,
                          size_t num_scans,
                          const std::string& gt_poses,
                          std::vector<Isometry3d>* truth,
                          std::vector<Isometry3d>* odometry,
                          std::string* error);

}  // namespace tools
}  // namespace mlndt
