#pragma once

// The pieces of mlndt_posegraph's joint problem (pose_graph.h) that are not
// ML-NDT pairs: a world_from_scan pose in the layout Ceres optimises, and an
// odometry factor that ties two scans' poses to a measured relative motion
// with a stated noise (a between-factor, as in GTSAM or g2o pose graphs).

#include <ceres/problem.h>

#include "mlndt/common/types.h"

namespace mlndt {

// world_from_scan as two parameter blocks.
struct PoseBlocks {
  double rotation[4] = {0.0, 0.0, 0.0, 1.0};  // Eigen quaternion x, y, z, w.
  double translation[3] = {0.0, 0.0, 0.0};    // [m].

  static PoseBlocks From(const Isometry3d& world_from_scan);
  Isometry3d ToIsometry() const;
};

// The stated noise of a measured relative motion: one standard deviation
// per translation axis [m] and per rotation axis [deg], each at least 1e-4
// (OdometryNoiseTable, pose_graph_option_table.h).
struct OdometryNoise {
  double sigma_m = 0.05;
  double sigma_deg = 0.5;
};

// Adds the residual r = [t_e / sigma_m; theta_e / sigma_rad] of the error
// E = measured^-1 (T_i^-1 T_j) (t_e its translation, theta_e its rotation
// vector), i.e. information diag(1/sigma^2), on the blocks of scans i and j.
// Sets ceres::EigenQuaternionManifold on a rotation block that has none.
ceres::ResidualBlockId AddOdometryFactor(const Isometry3d& measured_i_from_j,
                                         const OdometryNoise& noise,
                                         PoseBlocks* pose_i,
                                         PoseBlocks* pose_j,
                                         ceres::Problem* problem);

}  // namespace mlndt
