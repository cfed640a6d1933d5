#include "tools/cli/tool_table_flags.h"

#include "tools/cli/adaptive_start_layer_flags.h"
#include "tools/cli/bench_flags.h"
#include "tools/cli/localizer_flags.h"
#include "tools/cli/map_build_flags.h"
#include "tools/cli/odometry_flags.h"
#include "tools/cli/pose_graph_flags.h"
#include "tools/cli/sequence_flags.h"
#include "tools/cli/suite_plan_flags.h"
#include "tools/cli/trajectory_evaluation_flags.h"

namespace mlndt {
namespace tools {

std::vector<const TableFlags*> ToolTableFlags() {
  return {&MapBuildFlags(),
          &LocalizerFlags(),
          &OdometryFlags(),
          &TrajectoryEvaluationFlags(),
          &AdaptiveStartLayerFlags(),
          &PoseGraphFlags(),
          &SequenceFlags(),
          &SuitePlanFlags(),
          &BenchFlags()};
}

}  // namespace tools
}  // namespace mlndt
