#include "lab/sim/rosette_sensor.h"

#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {

bool RosetteSensorOptions::IsValid(std::string* error) const {
  if (!(horizontal_fov_deg > 0.0 && horizontal_fov_deg < 180.0 &&
        vertical_fov_deg > 0.0 && vertical_fov_deg < 180.0)) {
    *error = "rosette sensor: the field of view must be in (0, 180) deg";
    return false;
  }
  if (num_lasers < 1 || !(laser_spacing_deg >= 0.0)) {
    *error = "rosette sensor: num_lasers >= 1 and laser_spacing_deg >= 0";
    return false;
  }
  if (!(points_per_second > 0.0 && frame_period_s > 0.0 &&
        points_per_second * frame_period_s <= 1e7)) {
    *error =
        "rosette sensor: points_per_second and frame_period_s must be > 0, "
        "at most 1e7 rays per frame";
    return false;
  }
  if (!(prism_frequency_1_hz > 0.0 && prism_frequency_2_hz > 0.0)) {
    *error = "rosette sensor: the prism frequencies must be > 0";
    return false;
  }
  return true;
}

std::vector<SensorRay> RosetteRays(const RosetteSensorOptions& options,
                                   double frame_start_s) {
  const long samples =
      std::lround(options.points_per_second * options.frame_period_s);
  const double dt = options.frame_period_s / static_cast<double>(samples);
  const double half_h = 0.5 * options.horizontal_fov_deg * kDegToRad;
  const double half_v = 0.5 * options.vertical_fov_deg * kDegToRad;
  const double w1 = 2.0 * M_PI * options.prism_frequency_1_hz;
  const double w2 = 2.0 * M_PI * options.prism_frequency_2_hz;
  std::vector<SensorRay> rays;
  rays.reserve(static_cast<size_t>(samples));
  for (long k = 0; k < samples; ++k) {
    const int c = static_cast<int>(k % options.num_lasers);
    const double t = frame_start_s + dt * static_cast<double>(k);
    // Each laser sees the prisms at its own phase (evenly spread).
    const double phase = 2.0 * M_PI * c / options.num_lasers;
    const double a1 = w1 * t + phase;
    const double a2 = w2 * t - phase;
    const double u = 0.5 * (std::cos(a1) + std::cos(a2));
    const double v = 0.5 * (std::sin(a1) - std::sin(a2));
    const double offset =
        (c - 0.5 * (options.num_lasers - 1)) * options.laser_spacing_deg;
    SensorRay ray;
    ray.direction =
        DirectionFromAngles(u * half_h, v * half_v + offset * kDegToRad);
    ray.time_s = dt * static_cast<double>(k);
    ray.channel = c;
    rays.push_back(ray);
  }
  return rays;
}

bool RosetteCovers(const RosetteSensorOptions& options,
                   const Eigen::Vector3d& direction) {
  if (direction.x() <= 0.0) return false;
  const double azimuth = std::atan2(direction.y(), direction.x());
  const double elevation =
      std::atan2(direction.z(), direction.head<2>().norm());
  const double u = azimuth / (0.5 * options.horizontal_fov_deg * kDegToRad);
  const double v = elevation / (0.5 * options.vertical_fov_deg * kDegToRad);
  return u * u + v * v <= 1.0;
}

}  // namespace sim
}  // namespace mlndt
