#pragma once

// A row of furnished rooms along x, joined by doorways on the centre line
// (y = 0): floor, ceiling, walls with door openings, and boxes for
// furniture (tables, shelves along the walls, cabinets) kept clear of the
// walkway through the doors.

#include <cstdint>
#include <string>

#include "lab/sim/scene.h"

namespace mlndt {
namespace sim {

struct RoomsSceneOptions {
  int min_rooms = 3;  // >= 1.
  int max_rooms = 5;
  double min_room_length_m = 4.0;  // Along x.
  double max_room_length_m = 9.0;
  double min_room_width_m = 4.0;  // Along y.
  double max_room_width_m = 8.0;
  double min_height_m = 2.5;
  double max_height_m = 3.5;
  int max_furniture_per_room = 6;

  bool IsValid(std::string* error) const;
};

Scene BuildRoomsScene(const RoomsSceneOptions& options, uint64_t seed);

}  // namespace sim
}  // namespace mlndt
