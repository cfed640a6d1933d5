#include "lab/eval/trajectory.h"

#include <glog/logging.h>

#include <cmath>

namespace mlndt {

Trajectory::Trajectory(const std::vector<Isometry3d>& world_from_sensor) {
  timestamps_s_.reserve(world_from_sensor.size());
  poses_.reserve(world_from_sensor.size());
  for (size_t i = 0; i < world_from_sensor.size(); ++i) {
    Add(static_cast<double>(i), world_from_sensor[i]);
  }
}

void Trajectory::Add(double timestamp_s, const Isometry3d& world_from_sensor) {
  CHECK(std::isfinite(timestamp_s)) << "timestamp " << timestamp_s;
  CHECK(timestamps_s_.empty() || timestamp_s > timestamps_s_.back())
      << "timestamp " << timestamp_s << " after " << timestamps_s_.back()
      << ": timestamps must increase strictly";
  timestamps_s_.push_back(timestamp_s);
  poses_.push_back(world_from_sensor);
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
