#include "lab/sim/vegetation_scene.h"

#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"
#include "lab/sim/terrain.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

// A point at least `clear` from the line y = 0, within +-half in x and y.
Eigen::Vector2d OffTrack(double half, double clear, SimRandom* random) {
  return Eigen::Vector2d(random->Uniform(-half, half),
                         random->Sign() * random->Uniform(clear, half));
}

void AddTree(const Terrain& terrain,
             const Eigen::Vector2d& at,
             int leaves,
             SimRandom* random,
             TriangleMesh* mesh) {
  const double z = terrain.Height(at.x(), at.y());
  const double trunk = random->Uniform(2.5, 8.0);
  AddCylinder(Vector3d(at.x(), at.y(), z - 0.3),
              random->Uniform(0.1, 0.4),
              trunk + 0.3,
              8,
              mesh);
  const double r = random->Uniform(1.5, 4.0);
  const Vector3d crown(at.x(), at.y(), z + trunk + 0.7 * r);
  AddLeaves(crown,
            Vector3d(r, r, random->Uniform(0.7, 1.3) * r),
            leaves,
            random->Uniform(0.1, 0.2),
            random,
            mesh);
}

}  // namespace

bool VegetationSceneOptions::IsValid(std::string* error) const {
  if (!(half_size_m >= 20.0 && min_relief_m >= 0.0 &&
        max_relief_m >= min_relief_m && min_trees >= 0 &&
        max_trees >= min_trees && max_trees <= 5000 && leaves_per_crown >= 0 &&
        leaves_per_crown <= 20000 && bushes >= 0 && bushes <= 10000 &&
        track_half_width_m >= 1.0 && track_half_width_m < half_size_m &&
        path_half_length_m >= 5.0 && path_half_length_m < half_size_m)) {
    *error =
        "vegetation: need half_size_m >= 20, relief >= 0, trees in [0, 5000], "
        "leaves_per_crown in [0, 20000], bushes in [0, 10000], "
        "track_half_width_m in [1, half_size_m), path_half_length_m in [5, "
        "half_size_m), each max >= its min";
    return false;
  }
  return true;
}

Scene BuildVegetationScene(const VegetationSceneOptions& options,
                           uint64_t seed) {
  SimRandom random(seed, "vegetation");
  Scene scene;
  scene.kind = "vegetation";
  scene.seed = seed;
  const double relief =
      random.Uniform(options.min_relief_m, options.max_relief_m);
  const Terrain terrain(5, relief, 15.0, 60.0, &random);
  const double h = options.half_size_m + 30.0;
  AddHeightField(
      -h,
      h,
      -h,
      h,
      2.0,
      [&](double x, double y) { return terrain.Height(x, y); },
      &scene.mesh);
  const int trees = random.UniformInt(options.min_trees, options.max_trees);
  const double clear = options.track_half_width_m;
  for (int k = 0; k < trees; ++k) {
    AddTree(terrain,
            OffTrack(options.half_size_m, clear, &random),
            options.leaves_per_crown,
            &random,
            &scene.mesh);
  }
  for (int k = 0; k < options.bushes; ++k) {
    const Eigen::Vector2d at = OffTrack(options.half_size_m, clear, &random);
    const double r = random.Uniform(0.5, 1.5);
    AddLeaves(Vector3d(at.x(), at.y(), terrain.Height(at.x(), at.y()) + r),
              Vector3d(r, r, 0.8 * r),
              static_cast<int>(150 * r * r),
              random.Uniform(0.08, 0.15),
              &random,
              &scene.mesh);
  }
  const double p = options.path_half_length_m;
  for (double x = -p; x <= p + 1e-9; x += 2.0) {
    scene.path.points.push_back(Vector3d(x, 0.0, terrain.Height(x, 0.0)));
  }
  scene.path.lateral_half_width_m = 0.5 * clear;
  scene.parameters = {{"relief_m", relief},
                      {"trees", trees},
                      {"leaves_per_crown", options.leaves_per_crown},
                      {"bushes", options.bushes}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
