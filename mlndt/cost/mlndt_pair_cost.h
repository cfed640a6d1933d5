#pragma once

// The ML-NDT residual of one sampled point of scan j against the map of
// scan i, with both scans' poses free: the pair residual of a pose graph or
// bundle adjustment over many scans.
//
// Poses are world_from_scan, each an Eigen quaternion (x, y, z, w; use
// ceres::EigenQuaternionManifold) and a translation [m]:
//
//   w  = R_j p + t_j                 p in scan j -> world
//   x' = R_i^T (w - t_i)             world -> scan i (the map's frame)
//   e  = x' - mu                     (Eq. 9), mu of the cell x' falls in
//   r  = W e,  W^T W = C^-1          so ||r||^2 = e^T C^-1 e (Eq. 10)
//
// x' depends on the poses only through scan_i_from_scan_j = pose_i^-1 pose_j,
// so the residual is unchanged when both poses move by the same world
// transform, and with pose i = identity it is MlNdtPointCostQuaternion on
// pose j. The cell lookup (scalar part of the Jet) and the unmatched-point
// rule are those of WhitenedCellResidual (mlndt_point_cost.h).
//
// The layer is fixed at construction, or read through a LayerBinding at every
// evaluation (layer_binding.h): one set of residual blocks per pair then
// serves every layer of the schedule (schedule/problem_schedule.h).
//
// Lifetime: the functor keeps a pointer to the NdtLayer (or the binding),
// which must outlive every ceres::Problem that uses it.

#include <ceres/autodiff_cost_function.h>
#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class MlNdtPairCost {
 public:
  // `layer`: a layer of scan i's map (or a binding to one); `input_point`: a
  // point of scan j, in scan j's frame [m].
  MlNdtPairCost(LayerSource layer,
                const Eigen::Vector3d& input_point,
                UnmatchedPolicy policy)
      : layer_(layer), input_point_(input_point), policy_(policy) {}

  // world_from_scan_i and world_from_scan_j: quaternions (x, y, z, w, unit
  // norm) and translations [m].
  template <typename T>
  bool operator()(const T* rotation_i,
                  const T* translation_i,
                  const T* rotation_j,
                  const T* translation_j,
                  T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_i(rotation_i);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_i(translation_i);
    const Eigen::Map<const Eigen::Quaternion<T>> q_j(rotation_j);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_j(translation_j);
    const Eigen::Matrix<T, 3, 1> world = q_j * input_point_.cast<T>() + t_j;
    const Eigen::Matrix<T, 3, 1> in_scan_i = q_i.conjugate() * (world - t_i);
    WhitenedCellResidual(layer_.layer(), policy_, in_scan_i, residual);
    return true;
  }

  static ceres::CostFunction* Create(LayerSource layer,
                                     const Eigen::Vector3d& input_point,
                                     UnmatchedPolicy policy) {
    return new ceres::AutoDiffCostFunction<MlNdtPairCost, 3, 4, 3, 4, 3>(
        new MlNdtPairCost(layer, input_point, policy));
  }

 private:
  const LayerSource layer_;
  const Eigen::Vector3d input_point_;
  const UnmatchedPolicy policy_;
};

}  // namespace mlndt
