#pragma once

// A simulated sensor trajectory: the sensor's pose at each scan's stamp
// (world_from_sensor: p_world = P p_sensor; the sensor frame has x forward,
// y left, z up) and the stamps.

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace sim {

struct SimTrajectory {
  std::string kind;  // "car", "handheld".
  std::vector<Isometry3d> world_from_sensor;
  std::vector<double> stamps_s;  // Absolute, increasing [s].

  // The body-frame twist per second (t [m/s], rotation vector [rad/s]) that
  // moves scan k's pose to scan k+1's in the time between their stamps
  // (TwistToMotion(v * dt) = P_k^-1 P_k+1); the last scan takes the one
  // before's. Zero with one scan.
  Vector6d Velocity(size_t k) const;
};

// R = Rz(yaw) Ry(pitch) Rx(roll), at `position` [m, rad].
Isometry3d PoseFromYawPitchRoll(const Vector3d& position,
                                double yaw,
                                double pitch,
                                double roll);

// The yaw, pitch and roll of a rotation (inverse of the above; pitch in
// [-pi/2, pi/2]).
Vector3d YawPitchRoll(const Matrix3d& rotation);

}  // namespace sim
}  // namespace mlndt
