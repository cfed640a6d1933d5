#include "lab/sim/corridor_scene.h"

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {

using Eigen::Vector2d;
using Eigen::Vector3d;

bool CorridorSceneOptions::IsValid(std::string* error) const {
  if (!(path_half_length_m >= 10.0 &&
        0.5 * length_m - path_half_length_m >= 250.0 && min_width_m >= 1.0 &&
        max_width_m >= min_width_m && min_height_m >= 2.0 &&
        max_height_m >= min_height_m)) {
    *error =
        "corridor: need path_half_length_m >= 10, length_m / 2 - "
        "path_half_length_m >= 250, width >= 1, height >= 2, each max >= its "
        "min";
    return false;
  }
  return true;
}

Scene BuildCorridorScene(const CorridorSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "corridor");
  Scene scene;
  scene.kind = "corridor";
  scene.seed = seed;
  const double w = random.Uniform(options.min_width_m, options.max_width_m);
  const double h = random.Uniform(options.min_height_m, options.max_height_m);
  const double x0 = -0.5 * options.length_m;
  const double x1 = 0.5 * options.length_m;
  const double y = 0.5 * w;
  AddExtrudedProfile({Vector2d(-y, 0),
                      Vector2d(y, 0),
                      Vector2d(y, h),
                      Vector2d(-y, h),
                      Vector2d(-y, 0)},
                     x0,
                     x1,
                     &scene.mesh);
  // A cable tray under the ceiling on one side, and a handrail: the same
  // along the whole length, so the axis stays free.
  const double side = random.Sign();
  const bool tray = random.Bernoulli(0.5);
  const bool rail = random.Bernoulli(0.5);
  if (tray) {
    const double d = random.Uniform(0.2, 0.4);
    AddBox(Vector3d(x0, side > 0 ? y - d : -y, h - 0.35),
           Vector3d(x1, side > 0 ? y : -y + d, h - 0.25),
           &scene.mesh);
  }
  if (rail) {
    AddBox(Vector3d(x0, side > 0 ? -y : y - 0.08, 0.85),
           Vector3d(x1, side > 0 ? -y + 0.08 : y, 0.95),
           &scene.mesh);
  }
  const double p = options.path_half_length_m;
  scene.path.points = {Vector3d(-p, 0, 0), Vector3d(p, 0, 0)};
  scene.path.lateral_half_width_m = std::max(0.0, 0.5 * w - 0.5);
  scene.free_translations_world = {Vector3d::UnitX()};
  scene.parameters = {{"width_m", w},
                      {"height_m", h},
                      {"length_m", options.length_m},
                      {"cable_tray", tray ? 1.0 : 0.0},
                      {"handrail", rail ? 1.0 : 0.0}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
