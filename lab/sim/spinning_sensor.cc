#include "lab/sim/spinning_sensor.h"

#include <algorithm>
#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {
namespace {

std::vector<double> Uniform(int count, double low_deg, double high_deg) {
  std::vector<double> angles;
  for (int k = 0; k < count; ++k) {
    angles.push_back(low_deg + (high_deg - low_deg) * k / (count - 1));
  }
  return angles;
}

SpinningSensorOptions Make(std::vector<double> angles, double resolution) {
  SpinningSensorOptions options;
  options.vertical_angles_deg = std::move(angles);
  options.azimuth_resolution_deg = resolution;
  return options;
}

}  // namespace

bool SpinningSensorOptions::IsValid(std::string* error) const {
  if (vertical_angles_deg.empty()) {
    *error = "spinning sensor: no lasers";
    return false;
  }
  for (const double a : vertical_angles_deg) {
    if (!(a > -90.0 && a < 90.0)) {
      *error = "spinning sensor: a laser elevation is not in (-90, 90) deg";
      return false;
    }
  }
  if (!(azimuth_resolution_deg > 0.0 && azimuth_resolution_deg <= 10.0)) {
    *error = "spinning sensor: azimuth_resolution_deg must be in (0, 10]";
    return false;
  }
  if (!(sweep_period_s > 0.0)) {
    *error = "spinning sensor: sweep_period_s must be > 0";
    return false;
  }
  return true;
}

int SpinningSensorOptions::num_columns() const {
  return static_cast<int>(std::lround(360.0 / azimuth_resolution_deg));
}

// VLP-16 data sheet: 16 lasers 2 deg apart over +-15 deg; 0.2 deg at 10 Hz.
SpinningSensorOptions Vlp16Options() { return Make(Uniform(16, -15, 15), 0.2); }

// HDL-32E: 32 lasers 1.33 deg apart over -30.67..+10.67 deg; 0.16 deg.
SpinningSensorOptions Hdl32Options() {
  return Make(Uniform(32, -30.67, 10.67), 0.16);
}

// HDL-64E: an upper block of 32 lasers over -8.33..+2 deg (1/3 deg apart)
// and a lower block of 32 over -24.33..-8.83 deg (1/2 deg apart); 0.17 deg.
SpinningSensorOptions Hdl64Options() {
  std::vector<double> angles = Uniform(32, -24.33, -8.83);
  const std::vector<double> upper = Uniform(32, -8.33, 2.0);
  angles.insert(angles.end(), upper.begin(), upper.end());
  return Make(angles, 0.17);
}

// OS1-64 (Gen 1): 64 lasers uniform over 33.2 deg; 1024 columns.
SpinningSensorOptions Os1_64Options() {
  return Make(Uniform(64, -16.6, 16.6), 360.0 / 1024.0);
}

// OS1-128 (Rev 6): 128 lasers uniform over 45 deg; 1024 columns.
SpinningSensorOptions Os1_128Options() {
  return Make(Uniform(128, -22.5, 22.5), 360.0 / 1024.0);
}

std::vector<SensorRay> SpinningRays(const SpinningSensorOptions& options) {
  const int columns = options.num_columns();
  std::vector<SensorRay> rays;
  rays.reserve(static_cast<size_t>(columns) *
               options.vertical_angles_deg.size());
  for (int c = 0; c < columns; ++c) {
    const double azimuth = M_PI - 2.0 * M_PI * c / columns;
    const double time = options.sweep_period_s * c / columns;
    for (size_t l = 0; l < options.vertical_angles_deg.size(); ++l) {
      SensorRay ray;
      ray.direction = DirectionFromAngles(
          azimuth, options.vertical_angles_deg[l] * kDegToRad);
      ray.time_s = time;
      ray.channel = static_cast<int>(l);
      rays.push_back(ray);
    }
  }
  return rays;
}

bool SpinningCovers(const SpinningSensorOptions& options,
                    const Eigen::Vector3d& direction) {
  const std::vector<double>& a = options.vertical_angles_deg;
  const double low = *std::min_element(a.begin(), a.end());
  const double high = *std::max_element(a.begin(), a.end());
  const double margin =
      a.size() > 1 ? 0.5 * (high - low) / (a.size() - 1) : 0.5;
  const double elevation =
      std::atan2(direction.z(), direction.head<2>().norm()) * kRadToDeg;
  return elevation >= low - margin && elevation <= high + margin;
}

}  // namespace sim
}  // namespace mlndt
