#include "tools/cli/pose_graph_flags.h"

#include "lab/runs/pose_graph_option_table.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kPoseGraphFlags(
    PoseGraphOwnOptionsTable(),
    "mlndt_posegraph",
    {{"max_iterations", "joint_max_iterations"}},
    {{"init_from_odometry", "init"}},
    {{"joint_point_blocks", "point_blocks"},
     {"odometry_sigma_m", "odometry_noise_sigma_m"},
     {"odometry_sigma_deg", "odometry_noise_sigma_deg"}},
    &IsSharedFlag,
    {{"joint_one_way", "both_directions"}});

}  // namespace

const TableFlags& PoseGraphFlags() { return kPoseGraphFlags; }

}  // namespace tools
}  // namespace mlndt
