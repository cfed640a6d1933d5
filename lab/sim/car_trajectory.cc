#include "lab/sim/car_trajectory.h"

#include <algorithm>
#include <cmath>

#include "lab/sim/sim_random.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace sim {

bool CarTrajectoryOptions::IsValid(std::string* error) const {
  if (!(min_step_m > 0.0 && max_step_m >= min_step_m && max_step_m <= 100.0 &&
        yaw_step_deg >= 0.0 && max_yaw_offset_deg >= 0.0 &&
        max_tilt_deg >= 0.0 && max_tilt_deg <= 30.0 && min_height_m >= 0.0 &&
        max_height_m >= min_height_m && scan_interval_s > 0.0)) {
    *error =
        "car trajectory: need 0 < min_step_m <= max_step_m <= 100, angles "
        ">= 0 (tilt <= 30 deg), 0 <= min_height_m <= max_height_m, "
        "scan_interval_s > 0";
    return false;
  }
  return true;
}

bool MakeCarTrajectory(const CarTrajectoryOptions& options,
                       const ScenePath& path,
                       int num_scans,
                       uint64_t seed,
                       SimTrajectory* trajectory,
                       std::string* error) {
  if (!options.IsValid(error)) return false;
  const double needed = (num_scans - 1) * options.max_step_m;
  if (num_scans < 1 || path.points.size() < 2 || path.Length() < needed) {
    *error = "car trajectory: " + std::to_string(num_scans) +
             " scans need a path of " + std::to_string(needed) + " m, the " +
             "scene's is " + std::to_string(path.Length()) + " m";
    return false;
  }
  SimRandom random(seed, "car_trajectory");
  *trajectory = SimTrajectory();
  trajectory->kind = "car";
  double s = random.Uniform(0.0, path.Length() - needed);
  const double height =
      random.Uniform(options.min_height_m, options.max_height_m);
  const double start = random.Uniform(0.0, 1000.0);
  double yaw_offset = 0.0;
  double lateral = random.Uniform(-1.0, 1.0) * path.lateral_half_width_m;
  const double max_yaw = options.max_yaw_offset_deg * kDegToRad;
  const double tilt = options.max_tilt_deg * kDegToRad;
  for (int k = 0; k < num_scans; ++k) {
    if (k > 0) {
      const double step =
          random.Uniform(options.min_step_m, options.max_step_m);
      yaw_offset = std::clamp(
          yaw_offset + random.Uniform(-1, 1) * options.yaw_step_deg * kDegToRad,
          -max_yaw,
          max_yaw);
      s += step * std::cos(yaw_offset);
      lateral = std::clamp(lateral + step * std::sin(yaw_offset),
                           -path.lateral_half_width_m,
                           path.lateral_half_width_m);
    }
    const Vector3d t = path.TangentAt(s);
    const Vector3d left = Vector3d(-t.y(), t.x(), 0.0).normalized();
    const Vector3d position =
        path.PointAt(s) + lateral * left + Vector3d(0, 0, height);
    const double slope = std::atan2(t.z(), t.head<2>().norm());
    trajectory->world_from_sensor.push_back(
        PoseFromYawPitchRoll(position,
                             std::atan2(t.y(), t.x()) + yaw_offset,
                             -slope + random.Uniform(-tilt, tilt),
                             random.Uniform(-tilt, tilt)));
    trajectory->stamps_s.push_back(start + k * options.scan_interval_s);
  }
  return true;
}

}  // namespace sim
}  // namespace mlndt
