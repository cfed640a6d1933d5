#include "tools/cli/trajectory_evaluation_flags.h"

#include "lab/eval/trajectory_evaluation_option_table.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kTrajectoryEvaluationFlags(
    TrajectoryEvaluationOptionsTable(), "mlndt_eval", {}, {}, nullptr);

}  // namespace

const TableFlags& TrajectoryEvaluationFlags() {
  return kTrajectoryEvaluationFlags;
}

}  // namespace tools
}  // namespace mlndt
