#pragma once

// The odometry's local map: the last keyframes' scans in the world frame,
// cropped to a radius around the sensor, as one layered NDT map (ML-NDT,
// Section 4). A scan registered onto it is matched against several views at
// once, so its error does not add up pair by pair as in scan-to-scan
// registration.

#include <deque>
#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"

namespace mlndt {

struct LocalMapOptions {
  // Keyframes kept (the oldest is dropped first). >= 1.
  int max_keyframes = 10;
  // Points farther than this from the newest keyframe's position are left
  // out of the map [m]. > 0.
  double radius_m = 100.0;
  // The map's layers (finest cell, division constant, ...).
  LayeredGridOptions grid;

  bool IsValid(std::string* error) const;
};

class LocalMap {
 public:
  explicit LocalMap(const LocalMapOptions& options) : options_(options) {}

  // Adds a keyframe (its scan in the sensor frame and world_from_sensor) and
  // rebuilds the map on `num_threads` threads. False with *error when the
  // map cannot be built (the previous map and keyframes are kept).
  bool AddKeyframe(const PointCloud& scan,
                   const Isometry3d& world_from_sensor,
                   int num_threads,
                   std::string* error);

  bool empty() const { return keyframes_.empty(); }
  // Drops every keyframe (the next AddKeyframe starts a new map).
  void Clear();
  size_t num_keyframes() const { return keyframes_.size(); }
  size_t num_points() const { return num_points_; }
  const LayeredGrid& grid() const { return grid_; }
  // world_from_sensor of the newest keyframe.
  const Isometry3d& last_keyframe() const { return keyframes_.back().pose; }
  double build_time_s() const { return build_time_s_; }

 private:
  struct Keyframe {
    PointCloud world_points;
    Isometry3d pose;
  };

  LocalMapOptions options_;
  std::deque<Keyframe> keyframes_;
  LayeredGrid grid_;
  size_t num_points_ = 0;
  double build_time_s_ = 0.0;
};

}  // namespace mlndt
