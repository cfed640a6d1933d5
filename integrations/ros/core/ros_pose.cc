#include "integrations/ros/core/ros_pose.h"

#include "mlndt/common/pose.h"

namespace mlndt {
namespace ros_core {

RosPose ToRosPose(const Isometry3d& parent_from_child) {
  RosPose pose;
  pose.position = parent_from_child.translation();
  pose.orientation = Eigen::Quaterniond(parent_from_child.linear());
  if (pose.orientation.w() < 0.0) {
    pose.orientation.coeffs() = -pose.orientation.coeffs();
  }
  return pose;
}

Isometry3d FromRosPose(const RosPose& pose) {
  Isometry3d transform = Isometry3d::Identity();
  transform.linear() = pose.orientation.normalized().toRotationMatrix();
  transform.translation() = pose.position;
  return transform;
}

Matrix6d RosTangentFromPoseVectorJacobian(const Vector6d& xi) {
  const Eigen::Matrix3d rx =
      Eigen::AngleAxisd(xi(3), Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d ry =
      Eigen::AngleAxisd(xi(4), Eigen::Vector3d::UnitY()).toRotationMatrix();
  Matrix6d jacobian = Matrix6d::Zero();
  jacobian.topLeftCorner<3, 3>().setIdentity();
  jacobian.block<3, 1>(3, 3) = Eigen::Vector3d::UnitX();
  jacobian.block<3, 1>(3, 4) = rx * Eigen::Vector3d::UnitY();
  jacobian.block<3, 1>(3, 5) = rx * ry * Eigen::Vector3d::UnitZ();
  return jacobian;
}

std::array<double, 36> ToRosCovariance(const Isometry3d& parent_from_child,
                                       const Matrix6d& xi_covariance,
                                       bool known) {
  std::array<double, 36> out{};
  if (!known || !xi_covariance.allFinite()) {
    out[0] = -1.0;
    return out;
  }
  const Matrix6d jacobian =
      RosTangentFromPoseVectorJacobian(IsometryToPoseVector(parent_from_child));
  const Matrix6d covariance = jacobian * xi_covariance * jacobian.transpose();
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) out[6 * r + c] = covariance(r, c);
  }
  return out;
}

}  // namespace ros_core
}  // namespace mlndt
