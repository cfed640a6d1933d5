#pragma once

// mlndt_posegraph's accuracy figures: for the initial (chained or odometry)
// and the jointly refined trajectory, the ATE after aligning the first poses
// (estimate_k -> gt_0 est_0^-1 est_k; ComputeAte with FIRST_POSE) and the
// mean relative pose error of consecutive scans (ComputeRpe, delta 1), see
// lab/eval/trajectory_metrics.h.

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "tools/common/json_output.h"

namespace mlndt {
namespace tools {

// Adds ate_alignment, ate_{initial,joint}_m and rpe_{initial,joint}
// ({"translation_m", "rotation_deg"}) to *json, `initial_name` naming the
// initial trajectory ("chained" or "odometry"); false with *error when a
// trajectory does not match the truth.
bool AddTrajectoryMetrics(const std::string& initial_name,
                          const std::vector<Isometry3d>& initial,
                          const std::vector<Isometry3d>& joint,
                          const std::vector<Isometry3d>& truth,
                          Json* json,
                          std::string* error);

}  // namespace tools
}  // namespace mlndt
