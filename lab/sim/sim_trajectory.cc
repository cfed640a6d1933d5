#include "lab/sim/sim_trajectory.h"

#include <algorithm>
#include <cmath>

#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {
namespace sim {

Vector6d SimTrajectory::Velocity(size_t k) const {
  const size_t n = world_from_sensor.size();
  if (n < 2) return Vector6d::Zero();
  const size_t a = k + 1 < n ? k : n - 2;
  const double dt = stamps_s[a + 1] - stamps_s[a];
  return MotionToTwist(world_from_sensor[a].inverse() *
                       world_from_sensor[a + 1]) /
         dt;
}

Isometry3d PoseFromYawPitchRoll(const Vector3d& position,
                                double yaw,
                                double pitch,
                                double roll) {
  Isometry3d pose = Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(yaw, Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch, Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll, Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = position;
  return pose;
}

Vector3d YawPitchRoll(const Matrix3d& r) {
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  const double yaw = std::atan2(r(1, 0), r(0, 0));
  const double roll = std::atan2(r(2, 1), r(2, 2));
  return Vector3d(yaw, pitch, roll);
}

}  // namespace sim
}  // namespace mlndt
