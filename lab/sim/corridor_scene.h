#pragma once

// A long straight corridor along x of constant rectangular section
// (optionally with a cable tray and a handrail that run its whole length):
// nothing changes along x, so the pose is free along the corridor's axis.
// It is long enough (length_m, centred on 0) that its ends are beyond
// every sensor's range from the path (|x| <= path_half_length_m).

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct CorridorSceneOptions {
  double length_m = 700.0;
  double path_half_length_m = 50.0;
  double min_width_m = 1.6;
  double max_width_m = 3.0;
  double min_height_m = 2.4;
  double max_height_m = 3.2;

  // The ends must be beyond 250 m (the sensors' largest range) from the
  // path: length_m / 2 - path_half_length_m >= 250.
  bool IsValid(std::string* error) const;
};

Scene BuildCorridorScene(const CorridorSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
