#pragma once

// The pair residual r = W (R_i^T (R_j p + t_j - t_i) - mu) and its Jacobian
// in the ambient coordinates of (q_i, t_i, q_j, t_j), shared by
// MlNdtPairCostAnalytic and MlNdtPairFactor (the derivation is in
// mlndt_pair_cost_analytic.h).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mlndt/cost/cell_match.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {
namespace internal {

// Columns: q_i (x, y, z, w), t_i, q_j, t_j.
using PairJacobian = Eigen::Matrix<double, 3, 14>;

// The four blocks' values.
struct PairPoses {
  Eigen::Map<const Eigen::Quaterniond> q_i;
  Eigen::Map<const Eigen::Vector3d> t_i;
  Eigen::Map<const Eigen::Quaterniond> q_j;
  Eigen::Map<const Eigen::Vector3d> t_j;
  explicit PairPoses(double const* const* parameters)
      : q_i(parameters[0]),
        t_i(parameters[1]),
        q_j(parameters[2]),
        t_j(parameters[3]) {}
};

// d Rot(q, x) / d (u, w) for q = (u, w), Rot Eigen's quaternion-vector
// product x + 2w (u x x) + 2 u x (u x x).
inline Eigen::Matrix<double, 3, 4> RotateJacobian(const Eigen::Vector3d& u,
                                                  double w,
                                                  const Eigen::Vector3d& x) {
  Eigen::Matrix3d skew;
  skew << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
  Eigen::Matrix<double, 3, 4> d;
  d.leftCols<3>() = 2.0 * (u.dot(x) * Eigen::Matrix3d::Identity() +
                           u * x.transpose() - 2.0 * x * u.transpose()) -
                    2.0 * w * skew;
  d.col(3) = 2.0 * u.cross(x);
  return d;
}

// *residual for `point` of scan j, and *jacobian unless null. False (both
// zero) when the policy leaves the point unmatched.
inline bool PairResidual(const NdtLayer& layer,
                         UnmatchedPolicy policy,
                         const Eigen::Vector3d& point,
                         const PairPoses& poses,
                         Eigen::Vector3d* residual,
                         PairJacobian* jacobian) {
  const Eigen::Vector3d v = poses.q_j * point + poses.t_j - poses.t_i;
  const Eigen::Quaterniond q_i_inverse = poses.q_i.conjugate();
  const Eigen::Vector3d x = q_i_inverse * v;  // In scan i's frame.
  const NdtCell* cell = MatchCell(layer, x, policy);
  if (cell == nullptr) {
    residual->setZero();
    if (jacobian != nullptr) jacobian->setZero();
    return false;
  }
  *residual = cell->whitening * (x - cell->mean);
  if (jacobian == nullptr) return true;
  // W R_i^T: the derivative of r by anything that moves v.
  const Eigen::Matrix3d w_rt = cell->whitening * q_i_inverse.toRotationMatrix();
  // Rot(conj(q_i), v): u -> -u, so d/du flips sign.
  Eigen::Matrix<double, 3, 4> d_i =
      RotateJacobian(q_i_inverse.vec(), poses.q_i.w(), v);
  d_i.leftCols<3>() *= -1.0;
  jacobian->block<3, 4>(0, 0) = cell->whitening * d_i;
  jacobian->block<3, 3>(0, 4) = -w_rt;
  jacobian->block<3, 4>(0, 7) =
      w_rt * RotateJacobian(poses.q_j.vec(), poses.q_j.w(), point);
  jacobian->block<3, 3>(0, 11) = w_rt;
  return true;
}

}  // namespace internal
}  // namespace mlndt
