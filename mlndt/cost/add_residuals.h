#pragma once

// The embedding API: adds ML-NDT residuals of an input scan against one layer
// of a reference map to a ceres::Problem the caller owns, on the caller's own
// pose blocks. This is how ML-NDT goes into a bundle-adjustment or pose-graph
// back end. (mlndt::Register's Ceres backend builds the same residuals,
// mlndt_point_cost.h, and keeps them from one layer stage to the next.)
//
// The residuals minimise the objective of `objective` (objective_options.h;
// its defaults are Register's): the unmatched-point policy goes into every
// functor, and one loss function made from objective.loss and loss_scale
// goes on every block added by one call.
//
// The layer is an NdtLayer, fixed, or a LayerBinding (layer_binding.h): then
// one Problem can move coarse-to-fine by rebinding, without new blocks.
//
// Ownership: the Problem owns the cost functions and the loss function
// (ceres::Problem::Options' default ownership; with DO_NOT_TAKE_OWNERSHIP
// for loss functions the loss would leak). The NdtLayer (or the binding and
// every layer bound while the Problem is evaluated) must outlive the Problem.

#include <ceres/problem.h>

#include <vector>

#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

// One residual block (3 residuals) per input point, on the 6-vector pose
// block `reference_from_input_xi` = (tx, ty, tz, alpha, beta, gamma) of
// Eq. (11). Returns the ids of the blocks added.
std::vector<ceres::ResidualBlockId> AddMlNdtResiduals(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    double* reference_from_input_xi,
    ceres::Problem* problem);

// The same residuals on a quaternion block (Eigen order x, y, z, w) and a
// translation block. Sets ceres::EigenQuaternionManifold on the rotation
// block unless the caller has already given it a manifold.
std::vector<ceres::ResidualBlockId> AddMlNdtResidualsQuaternion(
    LayerSource reference_layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    double* reference_from_input_rotation,
    double* reference_from_input_translation,
    ceres::Problem* problem);

}  // namespace mlndt
