#pragma once

// Analytic first and second derivatives of the transformed point
// x' = R(alpha, beta, gamma) x + t (Eqs. 6-8) with respect to
// xi = (tx, ty, tz, alpha, beta, gamma), for the hand-written Newton and
// Levenberg-Marquardt backends (Eqs. 13-14; Magnusson's thesis gives the same
// terms for this Euler-angle convention).
//
// With R = Rx Ry Rz, every derivative of R is a product of the elementary
// rotations and their derivatives, e.g. dR/dalpha = Rx' Ry Rz and
// d2R/dalpha dbeta = Rx' Ry' Rz. They depend on the angles only, so they are
// computed once per iteration; per point the derivatives are matrix-vector
// products:
//   d x' / d t        = I
//   d x' / d angle_k  = R_k x                 (R_k = dR / d angle_k)
//   d2 x' / d angle_k d angle_l = R_kl x      (zero for any translation term)

#include <Eigen/Core>

#include "mlndt/common/types.h"

namespace mlndt {

class TransformDerivatives {
 public:
  explicit TransformDerivatives(const Vector6d& reference_from_input_xi);

  const Matrix3d& rotation() const { return rotation_; }
  const Eigen::Vector3d& translation() const { return translation_; }

  // x' = R x + t.
  Eigen::Vector3d Transform(const Eigen::Vector3d& x) const {
    return rotation_ * x + translation_;
  }

  // d x' / d xi (3 x 6) = [I | AngleJacobian(x)].
  Eigen::Matrix<double, 3, 6> Jacobian(const Eigen::Vector3d& x) const;
  // d x' / d (alpha, beta, gamma) (3 x 3).
  Matrix3d AngleJacobian(const Eigen::Vector3d& x) const {
    Matrix3d a;
    for (int k = 0; k < 3; ++k) a.col(k) = first_[k] * x;
    return a;
  }

  // sum_i w_i d2 x'_i / d xi d xi for a weight vector w (3), as a 6 x 6
  // matrix: the second-order term of Eq. (14) with w = C^-1 e. Only the
  // angle block is non-zero.
  Matrix6d WeightedSecondDerivative(const Eigen::Vector3d& x,
                                    const Eigen::Vector3d& w) const;

 private:
  Matrix3d rotation_;
  Eigen::Vector3d translation_;
  Matrix3d first_[3];      // dR / d angle_k.
  Matrix3d second_[3][3];  // d2R / d angle_k d angle_l (symmetric in k, l).
};

}  // namespace mlndt
