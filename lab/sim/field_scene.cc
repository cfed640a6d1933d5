#include "lab/sim/field_scene.h"

#include <algorithm>
#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"
#include "lab/sim/terrain.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

// One object standing on the ground at x, on the side `side` of the path
// (y = 0), its footprint at least 4 m from the path and its centre at most
// `max_offset` from it.
void AddObject(const Terrain& terrain,
               double x,
               double side,
               double max_offset,
               SimRandom* random,
               TriangleMesh* mesh) {
  const int type = random->UniformInt(0, 4);
  Vector3d size;    // Footprint x, y and height.
  if (type == 0) {  // Shed.
    size = Vector3d(random->Uniform(2.5, 8.0),
                    random->Uniform(2.5, 6.0),
                    random->Uniform(2.2, 4.0));
  } else if (type == 4) {  // Fence: a thin wall.
    size = Vector3d(random->Uniform(8.0, 30.0), 0.1, random->Uniform(1.0, 1.8));
  } else {  // Pole, tree, rock: within a 3.5 m radius.
    size = Vector3d(3.5, 3.5, 0.0);
  }
  const double footprint = 0.5 * size.head<2>().norm();
  const double y =
      side *
      random->Uniform(4.0 + footprint, std::max(4.0 + footprint, max_offset));
  const double z = terrain.Height(x, y);
  const double yaw = random->Uniform(0.0, M_PI);
  if (type == 0 || type == 4) {
    AddYawedBox(Vector3d(x, y, z - 0.3 + 0.5 * size.z()), size, yaw, mesh);
  } else if (type == 1) {  // Pole.
    AddCylinder(Vector3d(x, y, z - 0.3),
                random->Uniform(0.1, 0.2),
                random->Uniform(4.0, 10.0),
                8,
                mesh);
  } else if (type == 2) {  // Tree.
    const double trunk = random->Uniform(1.5, 3.0);
    AddCylinder(Vector3d(x, y, z - 0.3),
                random->Uniform(0.15, 0.35),
                trunk + 0.3,
                8,
                mesh);
    const double r = random->Uniform(1.5, 3.5);
    AddBlob(Vector3d(x, y, z + trunk + 0.8 * r),
            Vector3d(r, r, r),
            2,
            0.2,
            random,
            mesh);
  } else {  // Rock.
    const double r = random->Uniform(0.5, 1.5);
    AddBlob(
        Vector3d(x, y, z), Vector3d(r, 0.8 * r, 0.6 * r), 1, 0.3, random, mesh);
  }
}

}  // namespace

bool FieldSceneOptions::IsValid(std::string* error) const {
  if (!(half_size_m >= 50.0 && ground_cell_m >= 0.5 &&
        ground_cell_m <= 0.1 * half_size_m && min_relief_m >= 0.0 &&
        max_relief_m >= min_relief_m && min_objects >= 0 &&
        max_objects >= min_objects && object_radius_m > 5.0 &&
        path_half_length_m >= 5.0 &&
        path_half_length_m + object_radius_m < half_size_m)) {
    *error =
        "field: need half_size_m >= 50, ground_cell_m in [0.5, half_size_m / "
        "10], relief >= 0, objects >= 0, object_radius_m > 5, "
        "path_half_length_m >= 5, path_half_length_m + object_radius_m < "
        "half_size_m, each max >= its min";
    return false;
  }
  return true;
}

Scene BuildFieldScene(const FieldSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "field");
  Scene scene;
  scene.kind = "field";
  scene.seed = seed;
  const double relief =
      random.Uniform(options.min_relief_m, options.max_relief_m);
  const Terrain terrain(4, relief, 30.0, 120.0, &random);
  const double h = options.half_size_m;
  AddHeightField(
      -h,
      h,
      -h,
      h,
      options.ground_cell_m,
      [&](double x, double y) { return terrain.Height(x, y); },
      &scene.mesh);
  const int objects =
      random.UniformInt(options.min_objects, options.max_objects);
  const double p = options.path_half_length_m;
  for (int k = 0; k < objects; ++k) {
    // Uniform along the path's extent, at least 4 m off the path's line.
    const double x = random.Uniform(-p - 10.0, p + 10.0);
    AddObject(terrain,
              x,
              random.Sign(),
              options.object_radius_m,
              &random,
              &scene.mesh);
  }
  for (double x = -p; x <= p + 1e-9; x += 2.0) {
    scene.path.points.push_back(Vector3d(x, 0.0, terrain.Height(x, 0.0)));
  }
  scene.path.lateral_half_width_m = 1.0;
  scene.parameters = {
      {"relief_m", relief}, {"objects", objects}, {"half_size_m", h}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
