#include "mlndt/common/pose.h"

namespace mlndt {

Isometry3d PoseVectorToIsometry(const Vector6d& xi) {
  Isometry3d transform = Isometry3d::Identity();
  transform.linear() = EulerRotation(xi(3), xi(4), xi(5));
  transform.translation() = xi.head<3>();
  return transform;
}

Vector6d IsometryToPoseVector(const Isometry3d& transform) {
  const Matrix3d& r = transform.linear();
  Vector6d xi;
  xi.head<3>() = transform.translation();
  // From Eq. (7): r02 = sin(beta), r12 = -sin(alpha) cos(beta),
  // r22 = cos(alpha) cos(beta), r01 = -cos(beta) sin(gamma), r00 = cos(beta)
  // cos(gamma).
  const double cos_beta = std::hypot(r(0, 0), r(0, 1));
  xi(4) = std::atan2(r(0, 2), cos_beta);
  if (cos_beta > 1e-9) {
    xi(3) = std::atan2(-r(1, 2), r(2, 2));
    xi(5) = std::atan2(-r(0, 1), r(0, 0));
  } else {
    // Gimbal lock (beta = +-90 deg): only alpha +- gamma is defined; take
    // gamma = 0, then r10 = sin(alpha) sin(beta) and r11 = cos(alpha).
    xi(5) = 0.0;
    xi(3) = std::atan2(r(1, 0) * (r(0, 2) > 0 ? 1.0 : -1.0), r(1, 1));
  }
  return xi;
}

Vector6d PoseVectorFromDegrees(double tx,
                               double ty,
                               double tz,
                               double alpha_deg,
                               double beta_deg,
                               double gamma_deg) {
  Vector6d xi;
  xi << tx, ty, tz, alpha_deg * kDegToRad, beta_deg * kDegToRad,
      gamma_deg * kDegToRad;
  return xi;
}

double RotationErrorRad(const Isometry3d& a, const Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

double TranslationErrorM(const Isometry3d& a, const Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace mlndt
