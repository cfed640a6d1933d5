#pragma once

// The paper's pose parameters xi = (tx, ty, tz, alpha, beta, gamma) (Eq. 11)
// with R = Rx(alpha) Ry(beta) Rz(gamma) (Eq. 7) and x' = R x + t (Eq. 6).
// Angles in radians, translations in metres. A pose vector always maps input
// points into the reference frame; name it so: `reference_from_input_xi`.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "mlndt/common/types.h"

namespace mlndt {

// R = Rx(alpha) Ry(beta) Rz(gamma) (Eq. 7), for any scalar type (Ceres Jets).
template <typename T>
Eigen::Matrix<T, 3, 3> EulerRotation(const T& alpha,
                                     const T& beta,
                                     const T& gamma) {
  using std::cos;
  using std::sin;
  const T ca = cos(alpha), sa = sin(alpha);
  const T cb = cos(beta), sb = sin(beta);
  const T cg = cos(gamma), sg = sin(gamma);
  Eigen::Matrix<T, 3, 3> r;
  r(0, 0) = cb * cg;
  r(0, 1) = -cb * sg;
  r(0, 2) = sb;
  r(1, 0) = ca * sg + sa * sb * cg;
  r(1, 1) = ca * cg - sa * sb * sg;
  r(1, 2) = -sa * cb;
  r(2, 0) = sa * sg - ca * sb * cg;
  r(2, 1) = sa * cg + ca * sb * sg;
  r(2, 2) = ca * cb;
  return r;
}

// x' = R(xi) x + t(xi) (Eq. 6) for a pose vector xi[6].
template <typename T>
Eigen::Matrix<T, 3, 1> TransformPoint(const T* xi, const Eigen::Vector3d& x) {
  return EulerRotation(xi[3], xi[4], xi[5]) * x.cast<T>() +
         Eigen::Matrix<T, 3, 1>(xi[0], xi[1], xi[2]);
}

// Pose vector <-> rigid transform.
Isometry3d PoseVectorToIsometry(const Vector6d& xi);
// Inverse of PoseVectorToIsometry; beta is returned in [-pi/2, pi/2], and at
// beta = +-pi/2 (gimbal lock) gamma = 0.
Vector6d IsometryToPoseVector(const Isometry3d& transform);

// Builds a pose vector from translation [m] and angles [deg] (tool flags).
Vector6d PoseVectorFromDegrees(double tx,
                               double ty,
                               double tz,
                               double alpha_deg,
                               double beta_deg,
                               double gamma_deg);

// Rotation angle [rad] of the relative rotation between two transforms, and
// the translation difference [m]: the error measures used in all reports.
double RotationErrorRad(const Isometry3d& a, const Isometry3d& b);
double TranslationErrorM(const Isometry3d& a, const Isometry3d& b);

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kRadToDeg = 180.0 / M_PI;

}  // namespace mlndt
