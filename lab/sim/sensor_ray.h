#pragma once

// One ray of a sensor's scan pattern, in the sensor frame (x forward, y
// left, z up), with the time it fires.

#include <Eigen/Core>
#include <cmath>

namespace mlndt {
namespace sim {

struct SensorRay {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // Unit length.
  // When it fires, relative to the scan's stamp (the sweep's start) [s].
  double time_s = 0.0;
  int channel = 0;  // Laser (ring) index.
};

// The unit direction of azimuth `azimuth` (from x towards y) and elevation
// `elevation` (from the x-y plane towards z) [rad].
inline Eigen::Vector3d DirectionFromAngles(double azimuth, double elevation) {
  return Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                         std::cos(elevation) * std::sin(azimuth),
                         std::sin(elevation));
}

}  // namespace sim
}  // namespace mlndt
