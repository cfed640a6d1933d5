#pragma once

// The ML-NDT residual of one sampled input point (Eq. 10):
//
//   x' = R(xi) x + t(xi)             (Eqs. 6-8)
//   e  = x' - mu                     (Eq. 9), mu of the cell x' falls in
//   r  = W e,  W^T W = C^-1          so ||r||^2 = e^T C^-1 e (Eq. 10)
//
// The cell is looked up inside operator() from the scalar part of the Jet
// (see jet_utils.h), so the association follows the pose as Ceres iterates;
// derivatives flow through x' only. cell_match.h decides what a point in no
// occupied cell contributes.
//
// Two parameterisations of the same residual:
//  - MlNdtPointCost: the paper's 6-vector xi = (tx, ty, tz, alpha, beta,
//  gamma).
//  - MlNdtPointCostQuaternion: an Eigen quaternion (x, y, z, w; use
//    ceres::EigenQuaternionManifold) and a translation, for back ends that
//    keep their poses that way.
//
// The layer is fixed at construction, or read through a LayerBinding at every
// evaluation (layer_binding.h), so that one cost function per point serves
// every layer of a registration.
//
// Lifetime: the functors keep a pointer to the NdtLayer (or the binding),
// which must outlive every ceres::Problem that uses them (like
// ceres::BiCubicInterpolator's Grid).

#include <ceres/autodiff_cost_function.h>
#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mlndt/common/pose.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/jet_utils.h"
#include "mlndt/cost/layer_binding.h"

namespace mlndt {

// r = W (x' - mu) for the cell MatchCell picks at x', or zero.
template <typename T>
void WhitenedCellResidual(const NdtLayer& layer,
                          UnmatchedPolicy policy,
                          const Eigen::Matrix<T, 3, 1>& x,
                          T* residual) {
  const Eigen::Vector3d value(
      ScalarPart(x(0)), ScalarPart(x(1)), ScalarPart(x(2)));
  const NdtCell* cell = MatchCell(layer, value, policy);
  Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
  if (cell == nullptr) {
    r.setZero();
    return;
  }
  r = cell->whitening.cast<T>() * (x - cell->mean.cast<T>());
}

// The same for Jets, with W and mu as the constants they are
// (JetTimesConstant, jet_utils.h): the same values, fewer products.
template <int N>
void WhitenedCellResidual(const NdtLayer& layer,
                          UnmatchedPolicy policy,
                          const Eigen::Matrix<ceres::Jet<double, N>, 3, 1>& x,
                          ceres::Jet<double, N>* residual) {
  const Eigen::Vector3d value(x(0).a, x(1).a, x(2).a);
  const NdtCell* cell = MatchCell(layer, value, policy);
  Eigen::Map<Eigen::Matrix<ceres::Jet<double, N>, 3, 1>> r(residual);
  if (cell == nullptr) {
    r.setZero();
    return;
  }
  Eigen::Matrix<ceres::Jet<double, N>, 3, 1> e = x;
  for (int i = 0; i < 3; ++i) e(i).a -= cell->mean(i);  // x - mu, Eq. (9).
  r = JetTimesConstant(cell->whitening, e);
}

class MlNdtPointCost {
 public:
  MlNdtPointCost(LayerSource layer,
                 const Eigen::Vector3d& input_point,
                 UnmatchedPolicy policy)
      : layer_(layer), input_point_(input_point), policy_(policy) {}

  template <typename T>
  bool operator()(const T* reference_from_input_xi, T* residual) const {
    WhitenedCellResidual(
        layer_.layer(),
        policy_,
        CachedTransformPoint(reference_from_input_xi, input_point_),
        residual);
    return true;
  }

  // `layer`: an NdtLayer (fixed) or a LayerBinding (read at every evaluation).
  static ceres::CostFunction* Create(LayerSource layer,
                                     const Eigen::Vector3d& input_point,
                                     UnmatchedPolicy policy) {
    return new ceres::AutoDiffCostFunction<MlNdtPointCost, 3, 6>(
        new MlNdtPointCost(layer, input_point, policy));
  }

 private:
  const LayerSource layer_;
  const Eigen::Vector3d input_point_;
  const UnmatchedPolicy policy_;
};

class MlNdtPointCostQuaternion {
 public:
  MlNdtPointCostQuaternion(LayerSource layer,
                           const Eigen::Vector3d& input_point,
                           UnmatchedPolicy policy)
      : layer_(layer), input_point_(input_point), policy_(policy) {}

  // rotation: Eigen quaternion coefficients (x, y, z, w); translation [m].
  template <typename T>
  bool operator()(const T* rotation, const T* translation, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q(rotation);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(translation);
    WhitenedCellResidual(layer_.layer(),
                         policy_,
                         Eigen::Matrix<T, 3, 1>(q * input_point_.cast<T>() + t),
                         residual);
    return true;
  }

  static ceres::CostFunction* Create(LayerSource layer,
                                     const Eigen::Vector3d& input_point,
                                     UnmatchedPolicy policy) {
    return new ceres::AutoDiffCostFunction<MlNdtPointCostQuaternion, 3, 4, 3>(
        new MlNdtPointCostQuaternion(layer, input_point, policy));
  }

 private:
  const LayerSource layer_;
  const Eigen::Vector3d input_point_;
  const UnmatchedPolicy policy_;
};

}  // namespace mlndt
