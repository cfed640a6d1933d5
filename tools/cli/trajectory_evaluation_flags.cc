#include "tools/cli/trajectory_evaluation_flags.h"

#include "lab/eval/trajectory_evaluation_option_table.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kTrajectoryEvaluationFlags(
    TrajectoryEvaluationOptionsTable(),
    "mlndt_eval",
    {},
    {},
    {{"max_time_difference", "max_time_difference_s"},
     {"segment_lengths", "segments_lengths_m"},
     {"segment_step", "segments_first_frame_step"}},
    nullptr);

}  // namespace

const TableFlags& TrajectoryEvaluationFlags() {
  return kTrajectoryEvaluationFlags;
}

}  // namespace tools
}  // namespace mlndt
