#pragma once

// A trajectory: world_from_sensor poses with their timestamps, as read from
// KITTI or TUM files (trajectory_io.h) or built from registration results.

#include <cstddef>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

// Poses in time order. Timestamps are in seconds and strictly increasing;
// pose i maps points of the sensor at timestamp_s(i) into the world frame.
// KITTI files have no timestamps: their trajectories use the index as the
// time (0, 1, 2, ...).
class Trajectory {
 public:
  Trajectory() = default;
  // Poses at times 0, 1, 2, ... (the KITTI convention).
  explicit Trajectory(const std::vector<Isometry3d>& world_from_sensor);

  // Appends a pose. CHECK-fails unless timestamp_s is finite and greater
  // than the last timestamp (for stamps already checked; TryAdd for
  // stamps from user data).
  void Add(double timestamp_s, const Isometry3d& world_from_sensor);
  // Appends a pose; false with *error naming both stamps, and nothing
  // added, unless timestamp_s is finite and greater than the last.
  bool TryAdd(double timestamp_s,
              const Isometry3d& world_from_sensor,
              std::string* error);

  size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }
  double timestamp_s(size_t i) const { return timestamps_s_.at(i); }
  const Isometry3d& world_from_sensor(size_t i) const { return poses_.at(i); }
  const std::vector<double>& timestamps_s() const { return timestamps_s_; }
  const std::vector<Isometry3d>& poses() const { return poses_; }

 private:
  std::vector<double> timestamps_s_;
  std::vector<Isometry3d> poses_;
};

// Path length from the first pose to pose i [m]: distances[0] = 0 and
// distances[i] = distances[i-1] + |t_i - t_{i-1}|, t the positions
// (trajectoryDistances of the KITTI odometry devkit). Empty for no poses.
std::vector<double> PathDistancesM(const std::vector<Isometry3d>& poses);

}  // namespace mlndt
