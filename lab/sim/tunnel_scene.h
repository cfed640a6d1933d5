#pragma once

// A long straight road tunnel along x of constant section: a road between
// raised walkways, vertical walls and an elliptic vault. Nothing changes
// along x, so the pose is free along the tunnel's axis; the ends are beyond
// every sensor's range from the path.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct TunnelSceneOptions {
  double length_m = 800.0;
  double path_half_length_m = 100.0;
  double min_width_m = 8.0;  // Wall to wall.
  double max_width_m = 12.0;
  double min_wall_height_m = 1.0;  // Where the vault starts.
  double max_wall_height_m = 3.0;
  int vault_segments = 32;  // >= 4.

  // As CorridorSceneOptions: the ends beyond 250 m from the path.
  bool IsValid(std::string* error) const;
};

Scene BuildTunnelScene(const TunnelSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
