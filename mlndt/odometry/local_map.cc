#include "mlndt/odometry/local_map.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/timer.h"

namespace mlndt {

bool LocalMapOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(max_keyframes, 1);
  MLNDT_OPTION_GT(radius_m, 0.0);
  return grid.IsValid(error);
}

void LocalMap::Clear() {
  keyframes_.clear();
  grid_ = LayeredGrid();
  num_points_ = 0;
}

bool LocalMap::AddKeyframe(const PointCloud& scan,
                           const Isometry3d& world_from_sensor,
                           int num_threads,
                           std::string* error) {
  const double start = NowSeconds();
  std::deque<Keyframe> keyframes = keyframes_;
  keyframes.push_back(
      {TransformCloud(world_from_sensor, scan), world_from_sensor});
  while (keyframes.size() > static_cast<size_t>(options_.max_keyframes)) {
    keyframes.pop_front();
  }
  const Eigen::Vector3d center = world_from_sensor.translation();
  const double radius2 = options_.radius_m * options_.radius_m;
  PointCloud points;
  for (const Keyframe& keyframe : keyframes) {
    for (const Eigen::Vector3d& p : keyframe.world_points.points()) {
      if ((p - center).squaredNorm() <= radius2) points.Add(p);
    }
  }
  LayeredGrid grid;
  if (!LayeredGrid::Build(options_.grid, points, num_threads, &grid, error)) {
    *error = "local map: " + *error;
    return false;
  }
  keyframes_ = std::move(keyframes);
  grid_ = std::move(grid);
  num_points_ = points.size();
  build_time_s_ = NowSeconds() - start;
  return true;
}

}  // namespace mlndt
