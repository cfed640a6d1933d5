#pragma once

// A Livox-Avia-like solid-state LiDAR with a non-repetitive rosette pattern
// (two counter-rotating Risley prisms): laser c points, at absolute time t,
// at
//   u(t) = (cos(2 pi f1 t + p_c) + cos(2 pi f2 t + q_c)) / 2,
//   v(t) = (sin(2 pi f1 t + p_c) - sin(2 pi f2 t + q_c)) / 2,   |(u, v)| <= 1,
// azimuth = u * horizontal_fov / 2, elevation = v * vertical_fov / 2 (plus
// a small per-laser elevation offset). With f1 / f2 irrational the curve
// never closes, so each frame (a window of absolute time) samples other
// directions than the last: non-repetitive. Points are densest at the
// centre of the field of view, as the Avia's.

#include <string>
#include <vector>

#include "lab/sim/sensor_ray.h"

namespace mlndt {
namespace sim {

struct RosetteSensorOptions {
  // The elliptic field of view [deg] (Avia data sheet: 70.4 x 77.2).
  double horizontal_fov_deg = 70.4;
  double vertical_fov_deg = 77.2;
  int num_lasers = 6;  // >= 1.
  // Elevation offset between neighbouring lasers [deg].
  double laser_spacing_deg = 0.6;
  // Samples per second over all lasers (Avia: 240,000) and the frame
  // length [s]: 24,000 rays per 0.1 s frame.
  double points_per_second = 240000.0;
  double frame_period_s = 0.1;
  // The prisms' rotation rates [Hz]; an irrational ratio.
  double prism_frequency_1_hz = 1217.3;
  double prism_frequency_2_hz = 1021.9;

  bool IsValid(std::string* error) const;
};

// The rays of the frame that starts at absolute time `frame_start_s` (so
// consecutive frames continue the curve); time_s is relative to it.
std::vector<SensorRay> RosetteRays(const RosetteSensorOptions& options,
                                   double frame_start_s);

// Whether a direction lies in the elliptic field of view.
bool RosetteCovers(const RosetteSensorOptions& options,
                   const Eigen::Vector3d& direction);

}  // namespace sim
}  // namespace mlndt
