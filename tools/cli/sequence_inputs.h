#pragma once

// mlndt_sequence's poses: the ground truth (--gt_poses) and the odometry of
// --init=poses:FILE, one pose per scan, checked against the scans before
// any pair is registered.

#include <string>
#include <vector>

#include "lab/runs/sequence_registration.h"
#include "mlndt/common/types.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// The adaptive start layer from mlndt_sequence's --adaptive_* flags
// (adaptive_start_layer_flags.h); false with *error naming the flag for a
// value out of range or fail rates not ascending.
bool AdaptiveOptionsFromFlags(AdaptiveStartLayerOptions* adaptive,
                              std::string* error);

// The scans of --scans=`scans_dir` (or --bag; at most `max_scans`, the
// pose, calib and times files left out; a bag's stamps checked by
// ScanInput::ReadBagStamps) and ReadSequenceRunPoses.
bool ReadSequenceInputs(const SequenceOptions& options,
                        const std::string& scans_dir,
                        const std::string& gt_poses,
                        int max_scans,
                        ScanInput* input,
                        std::vector<Isometry3d>* truth,
                        std::vector<Isometry3d>* odometry,
                        std::string* error);

}  // namespace tools
}  // namespace mlndt
