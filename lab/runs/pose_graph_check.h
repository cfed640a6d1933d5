#pragma once

// The verdict on mlndt_posegraph's joint result (pose_graph.h): a joint
// solve always "converges", so the poses it ends at are judged against the
// factors' own information.
//  - Each pair (i, i+1, and every extra pair): scan j registered onto scan
//    i's map again, from the joint relative pose. The pair must be usable
//    there (or DEGENERATE: then the NEES judges the directions it
//    constrains), and the joint relative pose must lie within the pair's own
//    information of the pair's optimum: NEES = e^T (w H / 2) e, e the pose
//    vector difference, H the registration's Gauss-Newton Hessian and w the
//    calibrated kCalibratedPairInformationScale (RunPoseGraph passes it
//    whatever --information_scale weighted the pairs with; the NEES is 6 on
//    average when consistent, docs/embedding.md).
//  - Each odometry factor: its whitened squared residual at the joint
//    poses, |t_e|^2 / sigma_m^2 + |theta_e|^2 / sigma_rad^2 (chi-square with
//    6 degrees of freedom when the stated noise is right), under
//    OdometryChi2Gate.
// A pose 5 m off, or an odometry that drifts 3 deg a scan, ends LOW_QUALITY.

#include <string>
#include <utility>
#include <vector>

#include "lab/runs/pose_graph_factors.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {

// A pair's NEES above this is not within its information: the calibration
// pairs average 6, the worst data set (koide3, whose reference itself is
// 0.48 deg uncertain) 131; a pose 10 cm or 1 deg off along a well
// constrained direction of a KITTI pair is thousands.
constexpr double kPairNeesGate = 500.0;
// The gate of each of `factors` odometry factors: the chi-square (6
// degrees of freedom) quantile that all of them stay under with 99.9 %
// when the stated noise is right (Bonferroni: 1 - 0.001 / factors per
// factor): 22.46 for one factor, 27.0 for 7, 35.2 for 249.
double OdometryChi2Gate(size_t factors);

struct PoseGraphPairCheck {
  int map_scan = 0;
  int point_scan = 0;
  // Of the registration from the joint relative pose, and whether it can
  // judge the joint poses (IsUsableTermination, or DEGENERATE).
  std::string termination;
  bool usable = false;
  double nees = 0.0;
  // The joint relative pose against the registration's result.
  double translation_m = 0.0;
  double rotation_deg = 0.0;
};

struct PoseGraphCheck {
  std::vector<PoseGraphPairCheck> pairs;
  // Whitened squared residual of each odometry factor (i, i+1).
  std::vector<double> odometry_chi2;
  // "CONVERGENCE", or "LOW_QUALITY" (a pair or factor does not fit) or
  // "FAILURE" (a pose or the cost is not finite), with `message` naming it.
  std::string verdict;
  std::string message;
};

// Checks `joint` (world_from_scan per scan) against the pairs (consecutive
// and `extra_pairs`, scans[j] onto maps[i]; `information_scale` is the w
// above) and the odometry factors (`odometry` empty: none).
PoseGraphCheck CheckJointPoses(
    const RegistrationOptions& registration,
    double information_scale,
    const std::vector<LayeredGrid>& maps,
    const std::vector<PointCloud>& scans,
    const std::vector<std::pair<int, int>>& extra_pairs,
    const std::vector<Isometry3d>& odometry,
    const OdometryNoise& noise,
    const std::vector<Isometry3d>& joint,
    double final_cost);

}  // namespace mlndt
