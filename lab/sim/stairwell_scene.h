#pragma once

// A stairwell: a closed shaft with switch-back stairs, two flights per
// storey (the first up along +x, the second back along -x beside it),
// landings at both ends, a balustrade on the inner edge of each flight and
// a door on each storey's landing. The path climbs the flights.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct StairwellSceneOptions {
  int storeys = 3;  // >= 1.
  double min_storey_height_m = 2.8;
  double max_storey_height_m = 3.4;
  double min_flight_width_m = 1.0;
  double max_flight_width_m = 1.4;

  bool IsValid(std::string* error) const;
};

Scene BuildStairwellScene(const StairwellSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
