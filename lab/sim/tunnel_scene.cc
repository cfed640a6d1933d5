#include "lab/sim/tunnel_scene.h"

#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {

using Eigen::Vector2d;
using Eigen::Vector3d;

bool TunnelSceneOptions::IsValid(std::string* error) const {
  if (!(path_half_length_m >= 10.0 &&
        0.5 * length_m - path_half_length_m >= 250.0 && min_width_m >= 6.0 &&
        max_width_m >= min_width_m && min_wall_height_m >= 0.5 &&
        max_wall_height_m >= min_wall_height_m && vault_segments >= 4)) {
    *error =
        "tunnel: need path_half_length_m >= 10, length_m / 2 - "
        "path_half_length_m >= 250, width >= 6, wall height >= 0.5, "
        "vault_segments >= 4, each max >= its min";
    return false;
  }
  return true;
}

Scene BuildTunnelScene(const TunnelSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "tunnel");
  Scene scene;
  scene.kind = "tunnel";
  scene.seed = seed;
  const double w = random.Uniform(options.min_width_m, options.max_width_m);
  const double wall =
      random.Uniform(options.min_wall_height_m, options.max_wall_height_m);
  const double rise = random.Uniform(0.6, 1.0) * 0.5 * w;
  const double walkway = random.Uniform(0.8, 1.5);
  const double step = random.Uniform(0.15, 0.3);
  const double y = 0.5 * w;
  std::vector<Vector2d> profile = {Vector2d(-y, wall),
                                   Vector2d(-y, step),
                                   Vector2d(-y + walkway, step),
                                   Vector2d(-y + walkway, 0),
                                   Vector2d(y - walkway, 0),
                                   Vector2d(y - walkway, step),
                                   Vector2d(y, step),
                                   Vector2d(y, wall)};
  for (int k = 1; k <= options.vault_segments; ++k) {
    const double a = M_PI * k / options.vault_segments;
    profile.emplace_back(y * std::cos(a), wall + rise * std::sin(a));
  }
  AddExtrudedProfile(
      profile, -0.5 * options.length_m, 0.5 * options.length_m, &scene.mesh);
  const double p = options.path_half_length_m;
  const double lane = random.Uniform(-0.25, 0.25) * (w - 2.0 * walkway);
  scene.path.points = {Vector3d(-p, lane, 0), Vector3d(p, lane, 0)};
  scene.path.lateral_half_width_m = 0.5;
  scene.free_translations_world = {Vector3d::UnitX()};
  scene.parameters = {{"width_m", w},
                      {"wall_height_m", wall},
                      {"vault_rise_m", rise},
                      {"walkway_m", walkway},
                      {"walkway_step_m", step},
                      {"length_m", options.length_m},
                      {"lane_y_m", lane}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
