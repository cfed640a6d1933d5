#pragma once

// A narrow solid-state LiDAR (MEMS or flash): a regular grid of directions
// over a small rectangular field of view, scanned row by row from the top.

#include <string>
#include <vector>

#include "lab/sim/sensor_ray.h"

namespace mlndt {
namespace sim {

struct RasterSensorOptions {
  // Field of view [deg], centred on x; each in (0, 120].
  double horizontal_fov_deg = 40.0;
  double vertical_fov_deg = 20.0;
  // Grid spacing [deg]; > 0, at most 1e6 rays.
  double horizontal_resolution_deg = 0.25;
  double vertical_resolution_deg = 0.25;
  double frame_period_s = 0.1;  // The rows take this long [s]; > 0.

  bool IsValid(std::string* error) const;
  int num_columns() const;
  int num_rows() const;
};

std::vector<SensorRay> RasterRays(const RasterSensorOptions& options);

bool RasterCovers(const RasterSensorOptions& options,
                  const Eigen::Vector3d& direction);

}  // namespace sim
}  // namespace mlndt
