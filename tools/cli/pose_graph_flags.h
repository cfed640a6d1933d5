#pragma once

// mlndt_posegraph's flags of PoseGraphOptions' own fields (table_flags.h,
// made from PoseGraphOwnOptionsTable): --neighbors, --joint_layers,
// --joint_max_iterations (max_iterations, kept apart from the
// registration's --max_final_iterations), --both_directions,
// --point_blocks, --information_scale, --odometry_noise_sigma_m,
// --odometry_noise_sigma_deg. init_from_odometry is set by the tool's
// --init.
// Linking this file gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& PoseGraphFlags();

}  // namespace tools
}  // namespace mlndt
