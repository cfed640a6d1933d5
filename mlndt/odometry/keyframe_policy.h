#pragma once

// When a registered scan becomes a keyframe of the local map: when the
// sensor has moved or turned far enough from the last keyframe (KISS-ICP and
// LIO front ends keep a map of scans spaced by motion, not by time, so a
// sensor at rest does not fill the map with copies of one view).

#include <string>

#include "mlndt/common/types.h"

namespace mlndt {

struct KeyframeOptions {
  // A scan is a keyframe when it is this far [m] from the last keyframe, or
  // turned this much [deg]. Both > 0.
  double min_translation_m = 0.5;
  double min_rotation_deg = 10.0;

  bool IsValid(std::string* error) const;
};

// Whether `world_from_sensor` is far enough from `last_keyframe`.
bool IsNewKeyframe(const KeyframeOptions& options,
                   const Isometry3d& last_keyframe,
                   const Isometry3d& world_from_sensor);

}  // namespace mlndt
