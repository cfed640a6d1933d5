#pragma once

// Whether a built map can be used for registration: the check a map passes
// before it is written (mlndt_map, BuildMapFromScans / BuildMapFromCloud)
// or handed out (Python LayeredMap.build). A map that fails it gives every
// registration a FAILURE, so it is refused where it is made, not where it
// is used.

#include <string>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {

// True when `map` has at least one layer, every layer has a finite cell
// edge in (0, kMaxCoordinateM] and at least one occupied cell, and the
// bounding box is finite and within kMaxCoordinateM (1e8 m,
// mlndt/common/rigid_transform.h) of the origin. False with *error saying
// which (e.g. "the map has 0 occupied cells on layer 3 of 5 (cell 1.2 m):
// too few points per cell").
bool CheckMapUsable(const LayeredGrid& map, std::string* error);

}  // namespace mlndt
