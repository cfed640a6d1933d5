#pragma once

// mlndt_posegraph's accuracy figures in its summary.json: for the initial
// (chained or odometry) and the jointly refined trajectory, the ATE after
// aligning the first poses and the mean RPE of consecutive scans
// (EvaluatePoseGraphAccuracy, lab/eval/posegraph_metrics.h).

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "tools/cli/json_output.h"

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
