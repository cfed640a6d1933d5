#pragma once

// mlndt_eval's flags of TrajectoryEvaluationOptions (table_flags.h, made
// from TrajectoryEvaluationOptionsTable): --alignment, --delta,
// --association, --max_time_difference_s, --segments_lengths_m,
// --segments_first_frame_step. No shared registration
// flag is linked with them. Linking this file gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& TrajectoryEvaluationFlags();

}  // namespace tools
}  // namespace mlndt
