#include "tools/cli/pose_graph_flags.h"

#include "lab/runs/pose_graph_option_table.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

const TableFlags kPoseGraphFlags(PoseGraphOwnOptionsTable(),
                                 "mlndt_posegraph",
                                 {{"max_iterations", "joint_max_iterations"}},
                                 {{"init_from_odometry", "init"}},
                                 &IsSharedFlag);

}  // namespace

const TableFlags& PoseGraphFlags() { return kPoseGraphFlags; }

}  // namespace tools
}  // namespace mlndt
