#pragma once

// A pose and its covariance in the form ROS messages take them
// (geometry_msgs/PoseWithCovariance), without the middleware's types.
//
// The covariance is 6x6 row-major over (x, y, z, rotation about X, about Y,
// about Z), the "fixed-axis representation" of the message definition: a
// small rotation about the axes of the parent frame (header.frame_id),
// R' = exp([w]x) R, and a translation in that frame. The library's
// covariance is of its pose vector xi = (t, alpha, beta, gamma) with R =
// Rx(alpha) Ry(beta) Rz(gamma) (mlndt/common/pose.h); it is mapped by the
// Jacobian of w and t with respect to xi at the pose:
//   w = e_x d(alpha) + Rx(alpha) e_y d(beta) + Rx(alpha) Ry(beta) e_z d(gamma).
// An unknown covariance (or one with infinite or NaN entries, a degenerate
// direction) is published as ROS marks one: element 0 = -1, the rest 0.

#include <array>

#include "mlndt/common/types.h"

namespace mlndt {
namespace ros_core {

struct RosPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  // Unit quaternion with w >= 0, as the tools' TUM files write it.
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

RosPose ToRosPose(const Isometry3d& parent_from_child);
Isometry3d FromRosPose(const RosPose& pose);

// The covariance of the pose vector xi at `parent_from_child` in the
// message's order; `known` false gives the unknown marker.
std::array<double, 36> ToRosCovariance(const Isometry3d& parent_from_child,
                                       const Matrix6d& xi_covariance,
                                       bool known);

// The Jacobian d(t, w)/d(xi) at the pose vector xi (exposed for tests).
Matrix6d RosTangentFromPoseVectorJacobian(const Vector6d& xi);

}  // namespace ros_core
}  // namespace mlndt
