#pragma once

// mlndt_posegraph's accuracy figures of one trajectory against the truth:
// the ATE after aligning the first poses (estimate_k -> gt_0 est_0^-1 est_k;
// ComputeAte with FIRST_POSE) and the mean relative pose error of
// consecutive scans (ComputeRpe, delta 1), see lab/eval/trajectory_metrics.h.
// The tool writes them for the initial and the jointly refined trajectory
// (tools/cli/posegraph_output.cc).

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

struct PoseGraphAccuracy {
  double ate_m = 0.0;              // RMSE after the first-pose alignment.
  double rpe_translation_m = 0.0;  // Mean over consecutive scans.
  double rpe_rotation_deg = 0.0;   // Mean over consecutive scans.
};

// The accuracy of `estimate` against `truth`; false with *error when the
// trajectories do not match (sizes, fewer than two poses).
bool EvaluatePoseGraphAccuracy(const std::vector<Isometry3d>& estimate,
                               const std::vector<Isometry3d>& truth,
                               PoseGraphAccuracy* accuracy,
                               std::string* error);

}  // namespace mlndt
