#pragma once

// Compact, versioned binary storage of a layered NDT map (the paper's storage
// argument: a map is a few thousand cells, far smaller than the scan).
//
// Layout, little-endian:
//   "MLNDTMAP" | uint32 version (1) | options (q, n, min points, eigen ratio,
//   eigen floor) | bounds (6 doubles) | uint64 points | per layer: origin (3
//   doubles), cell size (double), dims (3 int32), uint64 cells, then per cell:
//   int64 key, int32 count, mean (3 doubles), upper covariance (6 doubles) |
//   uint64 FNV-1a checksum of everything before it.
// W and C^-1 are recomputed on load.

#include <string>

#include "mlndt/grid/layered_grid.h"

namespace mlndt {

// Writes atomically (temporary file + rename). Returns false with *error.
bool SaveLayeredGrid(const std::string& path,
                     const LayeredGrid& grid,
                     std::string* error);

// Reads a map written by SaveLayeredGrid. A missing, truncated, corrupt or
// foreign file returns false with *error naming the file and the problem, and
// leaves *grid unchanged.
bool LoadLayeredGrid(const std::string& path,
                     LayeredGrid* grid,
                     std::string* error);

}  // namespace mlndt
