#include "lab/sim/street_scene.h"

#include <algorithm>
#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

// A building whose facade faces the street at |y| = facade_y (side = +1:
// the left row, y > 0), spanning [x0, x1].
void AddBuilding(double x0,
                 double x1,
                 double facade_y,
                 double side,
                 double height,
                 SimRandom* random,
                 TriangleMesh* mesh) {
  const double depth = 12.0;
  const double y_near = side * facade_y;
  const double y_far = side * (facade_y + depth);
  AddBox(Vector3d(x0, std::min(y_near, y_far), 0.0),
         Vector3d(x1, std::max(y_near, y_far), height),
         mesh);
  const int style = random->UniformInt(0, 2);
  const double floor_height = random->Uniform(2.8, 3.6);
  const double out = side * -1.0;  // Towards the street.
  for (double z = floor_height; z < height - 1.0; z += floor_height) {
    // Floor ledges, 0.15-0.3 m deep.
    const double ledge = random->Uniform(0.15, 0.3);
    AddBox(Vector3d(x0, std::min(y_near, y_near + out * ledge), z - 0.15),
           Vector3d(x1, std::max(y_near, y_near + out * ledge), z + 0.1),
           mesh);
  }
  if (style == 1) {  // Pilasters every 3-5 m.
    const double spacing = random->Uniform(3.0, 5.0);
    const double width = random->Uniform(0.3, 0.6);
    const double depth_out = random->Uniform(0.15, 0.35);
    for (double x = x0 + 0.5 * spacing; x < x1 - 0.5; x += spacing) {
      AddBox(Vector3d(x, std::min(y_near, y_near + out * depth_out), 0.0),
             Vector3d(
                 x + width, std::max(y_near, y_near + out * depth_out), height),
             mesh);
    }
  } else if (style == 2) {  // Balconies on upper floors.
    for (double z = floor_height; z < height - 2.0; z += floor_height) {
      for (double x = x0 + 1.0; x < x1 - 3.0; x += random->Uniform(4, 7)) {
        if (!random->Bernoulli(0.6)) continue;
        const double w = random->Uniform(1.5, 3.0);
        AddBox(Vector3d(x, std::min(y_near, y_near + out * 1.2), z),
               Vector3d(x + w, std::max(y_near, y_near + out * 1.2), z + 1.0),
               mesh);
      }
    }
  }
}

// One row of buildings along the street (side +1 left, -1 right).
void AddBuildingRow(const StreetSceneOptions& options,
                    double street_half_width,
                    double side,
                    SimRandom* random,
                    TriangleMesh* mesh) {
  double x = -0.5 * options.length_m;
  while (x < 0.5 * options.length_m) {
    const double width = random->Uniform(options.min_building_width_m,
                                         options.max_building_width_m);
    const double height = random->Uniform(options.min_building_height_m,
                                          options.max_building_height_m);
    const double setback =
        random->Bernoulli(0.5) ? 0.0 : random->Uniform(0.3, 2.5);
    AddBuilding(
        x, x + width, street_half_width + setback, side, height, random, mesh);
    x += width;
    if (random->Bernoulli(options.gap_probability)) {
      x += random->Uniform(3.0, 8.0);
    }
  }
}

// A parked car at (x, y), its length along x.
void AddCar(double x, double y, SimRandom* random, TriangleMesh* mesh) {
  const double length = random->Uniform(3.8, 5.0);
  const double width = random->Uniform(1.6, 1.9);
  const double yaw = random->Uniform(-0.05, 0.05);
  const double body = random->Uniform(0.6, 0.8);
  AddYawedBox(Vector3d(x, y, 0.3 + 0.5 * body),
              Vector3d(length, width, body),
              yaw,
              mesh);
  const double cabin = random->Uniform(0.4, 0.6);
  AddYawedBox(Vector3d(x - 0.1 * length, y, 0.3 + body + 0.5 * cabin),
              Vector3d(0.55 * length, width - 0.15, cabin),
              yaw,
              mesh);
}

void AddTree(const Vector3d& base, SimRandom* random, TriangleMesh* mesh) {
  const double trunk = random->Uniform(2.0, 3.5);
  AddCylinder(base, random->Uniform(0.12, 0.25), trunk, 8, mesh);
  const double r = random->Uniform(1.5, 3.0);
  AddBlob(base + Vector3d(0, 0, trunk + 0.8 * r),
          Vector3d(r, r, random->Uniform(0.8, 1.2) * r),
          2,
          0.15,
          random,
          mesh);
}

// Cars, poles and trees along one kerb.
void AddKerbObjects(const StreetSceneOptions& options,
                    double kerb_y,
                    double side,
                    SimRandom* random,
                    TriangleMesh* mesh) {
  const double half = 0.5 * options.length_m;
  for (double x = -half + 3.0; x < half - 3.0; x += 7.0) {
    if (random->Bernoulli(options.car_probability)) {
      AddCar(x + random->Uniform(-1.0, 1.0), kerb_y - side * 1.2, random, mesh);
    }
  }
  for (double x = -half + random->Uniform(0.0, options.pole_spacing_m);
       x < half;
       x += options.pole_spacing_m * random->Uniform(0.5, 1.5)) {
    AddCylinder(Vector3d(x, kerb_y + side * 0.5, 0.15),
                random->Uniform(0.08, 0.15),
                random->Uniform(4.0, 8.0),
                8,
                mesh);
  }
  for (double x = -half + 5.0; x < half - 5.0; x += 10.0) {
    if (random->Bernoulli(options.tree_probability)) {
      AddTree(Vector3d(x + random->Uniform(-2, 2), kerb_y + side * 1.5, 0.15),
              random,
              mesh);
    }
  }
}

}  // namespace

bool StreetSceneOptions::IsValid(std::string* error) const {
  if (!(length_m >= 60.0 && min_width_m >= 12.0 && max_width_m >= min_width_m &&
        min_building_width_m > 1.0 &&
        max_building_width_m >= min_building_width_m &&
        min_building_height_m > 2.0 &&
        max_building_height_m >= min_building_height_m &&
        pole_spacing_m > 1.0)) {
    *error =
        "street: need length_m >= 60, min_width_m >= 12, building widths > 1, "
        "heights > 2, pole_spacing_m > 1, each max >= its min";
    return false;
  }
  return true;
}

Scene BuildStreetScene(const StreetSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "street");
  Scene scene;
  scene.kind = "street";
  scene.seed = seed;
  const double width = random.Uniform(options.min_width_m, options.max_width_m);
  // Sidewalks leave a road of at least 9 m (two lanes with parked cars).
  const double sidewalk = random.Uniform(1.5, std::min(4.0, 0.5 * width - 4.5));
  const double kerb = random.Uniform(0.10, 0.18);
  const double half = 0.5 * options.length_m;
  const double road_half = 0.5 * width - sidewalk;
  scene.mesh.AddQuad(Vector3d(-half, -road_half, 0.0),
                     Vector3d(half, -road_half, 0.0),
                     Vector3d(half, road_half, 0.0),
                     Vector3d(-half, road_half, 0.0));
  for (const double side : {-1.0, 1.0}) {
    const double y0 = side * road_half;
    const double y1 = side * (0.5 * width + 3.0);
    AddBox(Vector3d(-half, std::min(y0, y1), 0.0),
           Vector3d(half, std::max(y0, y1), kerb),
           &scene.mesh);
    AddBuildingRow(options, 0.5 * width, side, &random, &scene.mesh);
    AddKerbObjects(options, y0, side, &random, &scene.mesh);
  }
  // The path: the lane centre, clear of the parked cars (2.5 m from kerb).
  const double lateral = std::max(0.3, 0.5 * (road_half - 2.5));
  const double lane = random.Uniform(-0.5, 0.5) * (road_half - 2.5);
  scene.path.points = {Vector3d(-0.35 * options.length_m, lane, 0.0),
                       Vector3d(0.35 * options.length_m, lane, 0.0)};
  scene.path.lateral_half_width_m = std::min(lateral, 1.0);
  scene.parameters = {{"width_m", width},
                      {"sidewalk_m", sidewalk},
                      {"kerb_m", kerb},
                      {"length_m", options.length_m},
                      {"lane_y_m", lane}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
