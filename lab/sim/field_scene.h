#pragma once

// Open country: gently rolling ground (a height field) with few objects
// (sheds, poles, trees, rocks, a fence), so that only a handful of shapes
// stand up from the ground. Whether a pair is constrained depends on which
// of them the sensor sees: pair_constraints.h decides it per pair.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct FieldSceneOptions {
  double half_size_m = 150.0;  // The ground spans +-this in x and y.
  double ground_cell_m = 4.0;  // Height field resolution.
  double min_relief_m = 0.1;   // Amplitude of the undulation.
  double max_relief_m = 0.6;
  int min_objects = 4;
  int max_objects = 10;
  double object_radius_m = 40.0;  // Objects within this of the path line.
  double path_half_length_m = 40.0;

  bool IsValid(std::string* error) const;
};

Scene BuildFieldScene(const FieldSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
