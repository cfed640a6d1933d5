#include "lab/sim/raster_sensor.h"

#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {

bool RasterSensorOptions::IsValid(std::string* error) const {
  if (!(horizontal_fov_deg > 0.0 && horizontal_fov_deg <= 120.0 &&
        vertical_fov_deg > 0.0 && vertical_fov_deg <= 120.0)) {
    *error = "raster sensor: the field of view must be in (0, 120] deg";
    return false;
  }
  if (!(horizontal_resolution_deg > 0.0 && vertical_resolution_deg > 0.0) ||
      static_cast<double>(num_columns()) * num_rows() > 1e6) {
    *error = "raster sensor: resolutions must be > 0, at most 1e6 rays";
    return false;
  }
  if (!(frame_period_s > 0.0)) {
    *error = "raster sensor: frame_period_s must be > 0";
    return false;
  }
  return true;
}

int RasterSensorOptions::num_columns() const {
  return 1 + static_cast<int>(
                 std::floor(horizontal_fov_deg / horizontal_resolution_deg));
}

int RasterSensorOptions::num_rows() const {
  return 1 + static_cast<int>(
                 std::floor(vertical_fov_deg / vertical_resolution_deg));
}

std::vector<SensorRay> RasterRays(const RasterSensorOptions& options) {
  const int columns = options.num_columns();
  const int rows = options.num_rows();
  std::vector<SensorRay> rays;
  rays.reserve(static_cast<size_t>(columns) * rows);
  for (int r = 0; r < rows; ++r) {
    const double elevation =
        0.5 * options.vertical_fov_deg - r * options.vertical_resolution_deg;
    for (int c = 0; c < columns; ++c) {
      const double azimuth = 0.5 * options.horizontal_fov_deg -
                             c * options.horizontal_resolution_deg;
      SensorRay ray;
      ray.direction =
          DirectionFromAngles(azimuth * kDegToRad, elevation * kDegToRad);
      ray.time_s = options.frame_period_s * r / rows;
      ray.channel = r;
      rays.push_back(ray);
    }
  }
  return rays;
}

bool RasterCovers(const RasterSensorOptions& options,
                  const Eigen::Vector3d& direction) {
  if (direction.x() <= 0.0) return false;
  const double azimuth = std::atan2(direction.y(), direction.x()) * kRadToDeg;
  const double elevation =
      std::atan2(direction.z(), direction.head<2>().norm()) * kRadToDeg;
  return std::abs(azimuth) <= 0.5 * options.horizontal_fov_deg &&
         std::abs(elevation) <= 0.5 * options.vertical_fov_deg;
}

}  // namespace sim
}  // namespace mlndt
