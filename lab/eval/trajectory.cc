#include "lab/eval/trajectory.h"

#include <glog/logging.h>

#include <cmath>
#include <sstream>

namespace mlndt {

Trajectory::Trajectory(const std::vector<Isometry3d>& world_from_sensor) {
  timestamps_s_.reserve(world_from_sensor.size());
  poses_.reserve(world_from_sensor.size());
  for (size_t i = 0; i < world_from_sensor.size(); ++i) {
    Add(static_cast<double>(i), world_from_sensor[i]);
  }
}

void Trajectory::Add(double timestamp_s, const Isometry3d& world_from_sensor) {
  std::string error;
  CHECK(TryAdd(timestamp_s, world_from_sensor, &error)) << error;
}

bool Trajectory::TryAdd(double timestamp_s,
                        const Isometry3d& world_from_sensor,
                        std::string* error) {
  if (!std::isfinite(timestamp_s) ||
      (!timestamps_s_.empty() && !(timestamp_s > timestamps_s_.back()))) {
    std::ostringstream message;
    message.precision(17);
    message << "timestamp " << timestamp_s;
    if (!timestamps_s_.empty()) message << " after " << timestamps_s_.back();
    message << ": timestamps must be finite and increase strictly";
    *error = message.str();
    return false;
  }
  timestamps_s_.push_back(timestamp_s);
  poses_.push_back(world_from_sensor);
  return true;
}

std::vector<double> PathDistancesM(const std::vector<Isometry3d>& poses) {
  std::vector<double> distances;
  if (poses.empty()) return distances;
  distances.reserve(poses.size());
  distances.push_back(0.0);
  for (size_t i = 1; i < poses.size(); ++i) {
    distances.push_back(
        distances.back() +
        (poses[i].translation() - poses[i - 1].translation()).norm());
  }
  return distances;
}

}  // namespace mlndt
