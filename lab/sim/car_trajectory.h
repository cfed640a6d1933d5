#pragma once

// A car-like trajectory along a scene's path: steps of min_step_m to
// max_step_m between scans, the heading following the path with a small
// random yaw offset (a random walk), the sensor at a fixed height on the
// roof with small roll and pitch from the suspension, and the slope of the
// path as pitch.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"
#include "lab/sim/sim_trajectory.h"

namespace mlndt {
namespace sim {

struct CarTrajectoryOptions {
  double min_step_m = 1.0;          // Along the path between scans; > 0.
  double max_step_m = 2.0;          // >= min.
  double yaw_step_deg = 1.0;        // Random walk of the yaw offset.
  double max_yaw_offset_deg = 3.0;  // |heading - path direction|.
  double max_tilt_deg = 0.5;        // |roll|, |pitch| from suspension.
  double min_height_m = 1.7;        // Sensor above the path.
  double max_height_m = 2.0;
  double scan_interval_s = 0.1;  // Between stamps; > 0.

  bool IsValid(std::string* error) const;
};

// False with *error when the options are invalid, num_scans < 1, or the
// path is shorter than the (num_scans - 1) longest steps.
bool MakeCarTrajectory(const CarTrajectoryOptions& options,
                       const ScenePath& path,
                       int num_scans,
                       uint64_t seed,
                       SimTrajectory* trajectory,
                       std::string* error);

}  // namespace sim
}  // namespace mlndt
