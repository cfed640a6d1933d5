#pragma once

// The embedding API for back ends that optimise many scan poses at once
// (pose graphs, bundle adjustment): adds the ML-NDT residuals of scan j's
// points against a layer of scan i's map, on the caller's world_from_scan
// pose blocks of both scans (mlndt_pair_cost.h), to a ceres::Problem the
// caller owns. AddMlNdtResidualsQuaternion (add_residuals.h) is the special
// case where scan i's pose is the identity.
//
// The layer is an NdtLayer, fixed, or a LayerBinding to a layer of scan i's
// map (layer_binding.h): then the same blocks, with the same points, move
// coarse to fine by rebinding, and SolveWithLayerSchedule
// (schedule/problem_schedule.h) runs the caller's Problem through the layer
// schedule that way.
//
// Ownership: the Problem owns the cost functions and the loss function (its
// default options). The NdtLayer (or the binding and every layer bound while
// the Problem is evaluated) must outlive the Problem.

#include <ceres/problem.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

// w that makes a pair's covariance (its J^T J inverted, which is
// RegistrationSummary::covariance for the same objective and samples,
// divided by w) consistent with its errors against the shared suite's
// references: mean NEES 6 over the 61 prior-start pairs of KITTI 00 and
// MulRan KAIST03 (6 / 108.4); 8.2 over the whole suite (docs/embedding.md).
constexpr double kCalibratedPairInformationScale = 0.055;

struct PairResidualOptions {
  // The unmatched-point policy and robust loss (objective_options.h).
  ObjectiveOptions objective;
  // false: one residual block (3 residuals) per point. true: one block for
  // all points of the pair with the same normal equations
  // (mlndt_pair_factor.h): far less memory and time in a pose graph, but the
  // residual vector has no per-point meaning.
  bool one_block_per_pair = false;
  // Per-point blocks: hand-written Jacobians (mlndt_pair_cost_analytic.h) or
  // auto-diff (mlndt_pair_cost.h) of the same residual. (The one-block form
  // is always analytic.)
  bool analytic_jacobians = true;
  // w: every point's term rho(s) becomes w rho(s) (ceres::ScaledLoss), so
  // the pair's information is w J^T J and its covariance 1/w times the
  // unit-information one. 1 treats every sampled point as an independent
  // measurement with its cell's covariance (the paper's objective; ~20x too
  // much information against odometry, IMU or GNSS factors). The default
  // is calibrated (above). A pair alone in a Problem lands on the same pose
  // whatever w is. In (0, 1e3].
  double information_scale = kCalibratedPairInformationScale;

  bool IsValid(std::string* error) const;
};

// One residual block (3 residuals) per input point of scan j (or one block
// for all, options.one_block_per_pair), on the blocks
// rotation_i (quaternion x, y, z, w), translation_i [m], rotation_j,
// translation_j of world_from_scan_i and world_from_scan_j. Sets
// ceres::EigenQuaternionManifold on each rotation block unless the caller
// has already given it a manifold. The two scans' blocks must be distinct
// (no self-pairs) and the options valid (both CHECKed). One loss made from
// the options goes on every block added. Returns the ids of the blocks
// added.
std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    LayerSource reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const PairResidualOptions& options,
    double* world_from_scan_i_rotation,
    double* world_from_scan_i_translation,
    double* world_from_scan_j_rotation,
    double* world_from_scan_j_translation,
    ceres::Problem* problem);

// The same with PairResidualOptions' defaults around `objective`.
std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    LayerSource reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const ObjectiveOptions& objective,
    double* world_from_scan_i_rotation,
    double* world_from_scan_i_translation,
    double* world_from_scan_j_rotation,
    double* world_from_scan_j_translation,
    ceres::Problem* problem);

}  // namespace mlndt
