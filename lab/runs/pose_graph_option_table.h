#pragma once

// The descriptions (mlndt/common/option_table.h) of the pose graph's own
// options (pose_graph.h; its registration's keep RegistrationOptionsTable,
// its pairs and odometry poses are data): name, unit, range and help of each
// field, from which mlndt_posegraph's flags, their checks and the option
// reference are made.

#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& OdometryNoiseTable();
// PoseGraphOptions without registration, extra_pairs, odometry and
// progress.
const OptionTable& PoseGraphOwnOptionsTable();

}  // namespace mlndt
