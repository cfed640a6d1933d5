#pragma once

// A straight street along x: road and raised sidewalks, a row of buildings
// on each side (set back by varying amounts, with gaps, floor ledges,
// pilasters or balconies), parked cars, poles and trees. Every dimension is
// drawn from the ranges below with the seed.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct StreetSceneOptions {
  double length_m = 240.0;  // Along x, centred on 0; >= 60.
  // Facade to facade [m].
  double min_width_m = 14.0;  // >= 12.
  double max_width_m = 24.0;
  // Building widths along the street and heights [m].
  double min_building_width_m = 6.0;
  double max_building_width_m = 25.0;
  double min_building_height_m = 6.0;
  double max_building_height_m = 30.0;
  double gap_probability = 0.15;  // A gap of 3-8 m after a building.
  double car_probability = 0.6;   // A parked car per 7 m of kerb.
  double pole_spacing_m = 20.0;   // Mean, each side.
  double tree_probability = 0.3;  // Per 10 m of sidewalk.

  bool IsValid(std::string* error) const;
};

Scene BuildStreetScene(const StreetSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
