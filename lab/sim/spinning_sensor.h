#pragma once

// A spinning multi-beam LiDAR (Velodyne, Ouster): `vertical_angles_deg`
// lasers fire together at each of 360 / azimuth_resolution_deg columns while
// the head turns once per sweep. The presets follow the sensors' data
// sheets (beam elevations, column counts at 10 Hz, ranges).

#include <string>
#include <vector>

#include "lab/sim/sensor_ray.h"

namespace mlndt {
namespace sim {

struct SpinningSensorOptions {
  // Elevation of each laser [deg], from the x-y plane towards z; each in
  // (-90, 90), at least one.
  std::vector<double> vertical_angles_deg;
  // Angle between columns [deg]; in (0, 10], and 360 / it columns (rounded)
  // make one sweep.
  double azimuth_resolution_deg = 0.2;
  double sweep_period_s = 0.1;  // One turn [s]; > 0.

  bool IsValid(std::string* error) const;
  int num_columns() const;
};

SpinningSensorOptions Vlp16Options();    // 16 beams, -15..15 deg, 0.2 deg.
SpinningSensorOptions Hdl32Options();    // 32 beams, -30.67..10.67 deg.
SpinningSensorOptions Hdl64Options();    // 64 beams, -24.33..2 deg.
SpinningSensorOptions Os1_64Options();   // 64 beams, -16.6..16.6, 1024 col.
SpinningSensorOptions Os1_128Options();  // 128 beams, -22.5..22.5.

// The rays of one sweep, column by column (the head turns from azimuth
// +180 deg clockwise, seen from above), lasers in order within a column.
std::vector<SensorRay> SpinningRays(const SpinningSensorOptions& options);

// Whether a direction lies within the lasers' elevations (half a beam
// spacing beyond the outermost ones).
bool SpinningCovers(const SpinningSensorOptions& options,
                    const Eigen::Vector3d& direction);

}  // namespace sim
}  // namespace mlndt
