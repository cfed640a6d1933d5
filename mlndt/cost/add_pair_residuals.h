#pragma once

// The embedding API for back ends that optimise many scan poses at once
// (pose graphs, bundle adjustment): adds the ML-NDT residuals of scan j's
// points against a layer of scan i's map, on the caller's world_from_scan
// pose blocks of both scans (mlndt_pair_cost.h), to a ceres::Problem the
// caller owns. AddMlNdtResidualsQuaternion (add_residuals.h) is the special
// case where scan i's pose is the identity.
//
// Ownership: the Problem owns the cost functions and the loss function (its
// default options). The NdtLayer must outlive the Problem.

#include <ceres/problem.h>

#include <Eigen/Core>
#include <vector>

#include "mlndt/cost/add_residuals.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

// One residual block (3 residuals) per input point of scan j, on the blocks
// rotation_i (quaternion x, y, z, w), translation_i [m], rotation_j,
// translation_j of world_from_scan_i and world_from_scan_j. Sets
// ceres::EigenQuaternionManifold on each rotation block unless the caller
// has already given it a manifold. The two scans' blocks must be distinct
// (no self-pairs). The objective's policy goes into every functor and one
// loss made from it on every block added (see add_residuals.h).
// Returns the ids of the blocks added.
std::vector<ceres::ResidualBlockId> AddMlNdtPairResiduals(
    const NdtLayer& reference_layer_of_scan_i,
    const std::vector<Eigen::Vector3d>& input_points_of_scan_j,
    const ObjectiveOptions& objective,
    double* world_from_scan_i_rotation,
    double* world_from_scan_i_translation,
    double* world_from_scan_j_rotation,
    double* world_from_scan_j_translation,
    ceres::Problem* problem);

}  // namespace mlndt
