#pragma once

// mlndt_posegraph's flags of PoseGraphOptions' own fields (table_flags.h,
// made from PoseGraphOwnOptionsTable): --neighbors, --joint_layers,
// --joint_max_iterations (max_iterations: --max_iterations is the
// registration's older flag name), --both_directions, --point_blocks,
// --information_scale, --odometry_noise_sigma_m, --odometry_noise_sigma_deg;
// the older names --joint_point_blocks, --odometry_sigma_m and
// --odometry_sigma_deg are aliases; the older --joint_one_way is an
// inverted alias (--both_directions=false). init_from_odometry is set by
// the tool's --init.
// Linking this file gives a tool these flags.

#include "tools/cli/table_flags.h"

namespace mlndt {
namespace tools {

const TableFlags& PoseGraphFlags();

}  // namespace tools
}  // namespace mlndt
