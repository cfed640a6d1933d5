#pragma once

// The shape of an NDT cell as the verdict reads it: which of its directions
// are thin (the surface's normal for a planar cell, the two across a line
// for a line cell). Not installed.

#include "mlndt/grid/ndt_layer.h"

namespace mlndt {
namespace internal {

// A cell direction counts as thin when its variance is below this fraction
// of the cell's largest.
constexpr double kThinCellDirection = 0.1;

// Which of the cell's directions (the rows of its W) are thin: one for a
// planar cell, two for a line cell.
Eigen::Array<bool, 3, 1> ThinCellDirections(const NdtCell& cell);

// `layer` without its line cells: the surfaces a scan saw, without the
// single rings crossing a cell that a spinning LiDAR's pattern leaves.
NdtLayer WithoutLineCells(const NdtLayer& layer);

}  // namespace internal
}  // namespace mlndt
