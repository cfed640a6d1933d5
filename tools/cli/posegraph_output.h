#pragma once

// What mlndt_posegraph writes: the trajectories (KITTI lines) and its JSON
// (docs/json_schema.md, "mlndt_posegraph").

#include <string>
#include <vector>

#include "lab/runs/pose_graph.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// trajectory_<initial>.txt and trajectory_joint.txt into `dir`.
bool WritePoseGraphTrajectories(const std::string& dir,
                                const PoseGraphSummary& summary,
                                std::string* error);

// The settings, the joint problem's facts and the times; with `truth`
// (empty: none) the trajectory metrics (ATE and RPE,
// lab/eval/posegraph_metrics.h).
bool PoseGraphJson(const PoseGraphOptions& options,
                   const PoseGraphSummary& summary,
                   const std::vector<Isometry3d>& truth,
                   Json* json,
                   std::string* error);

}  // namespace tools
}  // namespace mlndt
