#include "tools/common/tool_table_flags.h"

#include "tools/common/adaptive_start_layer_flags.h"
#include "tools/common/bench_flags.h"
#include "tools/common/localizer_flags.h"
#include "tools/common/map_build_flags.h"
#include "tools/common/odometry_flags.h"
#include "tools/common/pose_graph_flags.h"
#include "tools/common/sequence_flags.h"
#include "tools/common/suite_plan_flags.h"
#include "tools/common/trajectory_evaluation_flags.h"

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
