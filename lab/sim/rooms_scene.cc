#include "lab/sim/rooms_scene.h"

#include <algorithm>
#include <cmath>

#include "lab/sim/mesh_shapes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {
namespace {

using Eigen::Vector3d;

constexpr double kWall = 0.15;       // Wall thickness [m].
constexpr double kDoorHeight = 2.1;  // [m].
constexpr double kWalkway = 0.8;     // Kept clear either side of y = 0.

// A wall across the row at x, from y0 to y1, with a door of `door` width
// centred at y = door_y (no door when door <= 0).
void AddCrossWall(double x,
                  double y0,
                  double y1,
                  double height,
                  double door,
                  double door_y,
                  TriangleMesh* mesh) {
  const double a = x - 0.5 * kWall;
  const double b = x + 0.5 * kWall;
  if (door <= 0.0) {
    AddBox(Vector3d(a, y0, 0), Vector3d(b, y1, height), mesh);
    return;
  }
  AddBox(Vector3d(a, y0, 0), Vector3d(b, door_y - 0.5 * door, height), mesh);
  AddBox(Vector3d(a, door_y + 0.5 * door, 0), Vector3d(b, y1, height), mesh);
  AddBox(Vector3d(a, door_y - 0.5 * door, kDoorHeight),
         Vector3d(b, door_y + 0.5 * door, height),
         mesh);
}

// Furniture in the room [x0, x1] x [y0, y1], clear of |y| < kWalkway.
void AddFurniture(double x0,
                  double x1,
                  double y0,
                  double y1,
                  int count,
                  SimRandom* random,
                  TriangleMesh* mesh) {
  for (int k = 0; k < count; ++k) {
    const double side = random->Sign();
    const double edge = side > 0 ? y1 : y0;
    const int type = random->UniformInt(0, 2);
    Vector3d size;
    if (type == 0) {  // Table.
      size =
          Vector3d(random->Uniform(0.8, 2.0), random->Uniform(0.6, 1.0), 0.75);
    } else if (type == 1) {  // Shelf.
      size =
          Vector3d(random->Uniform(0.8, 2.0), 0.4, random->Uniform(1.6, 2.2));
    } else {  // Cabinet.
      size = Vector3d(random->Uniform(0.5, 1.2),
                      random->Uniform(0.4, 0.7),
                      random->Uniform(0.8, 1.3));
    }
    const double room_depth = std::abs(edge) - kWalkway - 0.2;
    if (size.y() > room_depth) continue;
    // Against the wall (shelves) or anywhere between walkway and wall.
    const double inner = kWalkway + 0.1 + 0.5 * size.y();
    const double outer = std::abs(edge) - kWall - 0.05 - 0.5 * size.y();
    const double y = side * (type == 1 ? outer : random->Uniform(inner, outer));
    const double x = random->Uniform(
        x0 + 0.5 * size.x() + 0.2,
        std::max(x0 + 0.5 * size.x() + 0.2, x1 - 0.5 * size.x() - 0.2));
    AddYawedBox(Vector3d(x, y, 0.5 * size.z()), size, 0.0, mesh);
  }
}

}  // namespace

bool RoomsSceneOptions::IsValid(std::string* error) const {
  if (!(min_rooms >= 1 && max_rooms >= min_rooms && max_rooms <= 50 &&
        min_room_length_m >= 2.0 && max_room_length_m >= min_room_length_m &&
        min_room_width_m >= 3.0 && max_room_width_m >= min_room_width_m &&
        min_height_m >= 2.3 && max_height_m >= min_height_m &&
        max_furniture_per_room >= 0)) {
    *error =
        "rooms: need 1 <= rooms <= 50, room length >= 2, width >= 3, height "
        ">= 2.3, furniture >= 0, each max >= its min";
    return false;
  }
  return true;
}

Scene BuildRoomsScene(const RoomsSceneOptions& options, uint64_t seed) {
  SimRandom random(seed, "rooms");
  Scene scene;
  scene.kind = "rooms";
  scene.seed = seed;
  const int rooms = random.UniformInt(options.min_rooms, options.max_rooms);
  const double height =
      random.Uniform(options.min_height_m, options.max_height_m);
  double x = 0.0;
  double y_min = 0.0, y_max = 0.0;
  for (int r = 0; r < rooms; ++r) {
    const double length =
        random.Uniform(options.min_room_length_m, options.max_room_length_m);
    const double width =
        random.Uniform(options.min_room_width_m, options.max_room_width_m);
    const double y0 = -width * random.Uniform(0.3, 0.7);
    const double y1 = y0 + width;
    AddBox(Vector3d(x, y0, -0.1), Vector3d(x + length, y1, 0), &scene.mesh);
    AddBox(Vector3d(x, y0, height),
           Vector3d(x + length, y1, height + 0.1),
           &scene.mesh);
    AddBox(Vector3d(x, y0 - kWall, 0),
           Vector3d(x + length, y0, height),
           &scene.mesh);
    AddBox(Vector3d(x, y1, 0),
           Vector3d(x + length, y1 + kWall, height),
           &scene.mesh);
    const double door = r == 0 ? 0.0 : random.Uniform(0.9, 1.4);
    AddCrossWall(x,
                 std::min(y0, y_min) - kWall,
                 std::max(y1, y_max) + kWall,
                 height,
                 door,
                 0.0,
                 &scene.mesh);
    AddFurniture(x,
                 x + length,
                 y0,
                 y1,
                 random.UniformInt(0, options.max_furniture_per_room),
                 &random,
                 &scene.mesh);
    y_min = y0;
    y_max = y1;
    x += length;
  }
  AddCrossWall(x, y_min - kWall, y_max + kWall, height, 0.0, 0.0, &scene.mesh);
  scene.path.points = {Vector3d(1.0, 0, 0), Vector3d(x - 1.0, 0, 0)};
  scene.path.lateral_half_width_m = 0.3;
  scene.parameters = {
      {"rooms", rooms}, {"height_m", height}, {"total_length_m", x}};
  return scene;
}

}  // namespace sim
}  // namespace mlndt
