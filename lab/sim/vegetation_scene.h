#pragma once

// A wood: rolling ground, trees (trunks and crowns of loose leaves) and
// bushes (clusters of leaves near the ground), with a clear track along x
// for the path. Leaves are small triangles at random orientations: no
// surface is planar beyond a few centimetres.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct VegetationSceneOptions {
  double half_size_m = 70.0;  // Trees within +-this in x and y.
  double min_relief_m = 0.2;
  double max_relief_m = 1.0;
  int min_trees = 60;
  int max_trees = 160;
  int leaves_per_crown = 900;
  int bushes = 80;
  double track_half_width_m = 2.5;  // No trunk or bush within it of y = 0.
  double path_half_length_m = 40.0;

  bool IsValid(std::string* error) const;
};

Scene BuildVegetationScene(const VegetationSceneOptions& options,
                           uint64_t seed);

}  // namespace sim
}  // namespace mlndt
