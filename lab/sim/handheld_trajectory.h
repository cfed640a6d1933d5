#pragma once

// A hand-held trajectory along a scene's path: between scans the carrier
// walks min_step_m to max_step_m (mostly forward, sometimes sideways or
// backward, within the path's lateral room) and turns the sensor by
// min_rotation_deg to max_rotation_deg about an axis near the vertical
// (the rest is roll and pitch shake), keeping the sensor within
// max_tilt_deg of level and its heading within max_heading_offset_deg of
// the path's direction (towards the path lookahead_m ahead).

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"
#include "lab/sim/sim_trajectory.h"

namespace mlndt {
namespace sim {

struct HandheldTrajectoryOptions {
  double min_step_m = 0.05;  // Walked between scans; > 0.
  double max_step_m = 0.6;
  double min_rotation_deg = 2.0;   // Rotation between scans; >= 0.
  double max_rotation_deg = 15.0;  // <= 90.
  // The rotation axis in the sensor frame is (shake g1, shake g2, +-1),
  // g Gaussian: the share of roll and pitch in each turn; >= 0.
  double shake = 0.35;
  double max_tilt_deg = 10.0;            // |roll|, |pitch|; in (0, 45].
  double max_heading_offset_deg = 35.0;  // In (0, 180].
  // The path's direction is taken towards its point this far ahead [m];
  // > 0.
  double lookahead_m = 2.5;
  double min_height_m = 1.2;  // Above the path.
  double max_height_m = 1.6;
  double scan_interval_s = 0.5;  // Between stamps (keyframes); > 0.

  bool IsValid(std::string* error) const;
};

// False with *error when the options are invalid, num_scans < 1, or the
// path is shorter than num_scans longest steps.
bool MakeHandheldTrajectory(const HandheldTrajectoryOptions& options,
                            const ScenePath& path,
                            int num_scans,
                            uint64_t seed,
                            SimTrajectory* trajectory,
                            std::string* error);

}  // namespace sim
}  // namespace mlndt
