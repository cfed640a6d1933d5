#pragma once

// The map of conventional single-grid NDT (Biber & Strasser; Magnusson's
// P2D-NDT; ML-NDT Section 3): one regular grid of cubic cells of edge k over
// the reference scan's bounding box, each cell with at least
// `min_points_per_cell` points keeping its mean (Eq. 2) and regularised
// unbiased covariance (Eq. 3, Section 4.1; see ndt_cell.h). It is an
// NdtLayer, so cell lookup works as on one layer of the ML-NDT map.
//
// Default cell size: the paper compares ML-NDT with NDT on cells "64 times
// smaller than the volume of the point cloud, which corresponds to the second
// layer representation in ML-NDT" (Section 5.1), i.e. k = (V / 64)^(1/3),
// the layer-2 edge of LayerCellSizes with q = 8 over the same box. PCL users
// typically run 1-2 m cells outdoors (cell_size_m).

#include <Eigen/Core>
#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

struct SingleGridOptions {
  // Cell edge k [m]. 0: the paper's layer-2 cell (V / 64)^(1/3). >= 0.
  double cell_size_m = 0.0;
  // A cell keeps a distribution when it holds at least this many points.
  // >= 4, as LayeredGridOptions::min_points_per_cell.
  int min_points_per_cell = LayeredGridOptions().min_points_per_cell;
  // Covariance regularisation (ndt_cell.h). min_eigenvalue_ratio in (0, 1],
  // min_eigenvalue_m2 >= 0.
  CellRegularization regularization;

  bool IsValid(std::string* error) const;
};

// The paper's comparison cell edge for a bounding box of the given extent
// [m]: one layer-2 cell of the ML-NDT map (q = 8), (V / 64)^(1/3), with
// degenerate extents raised as LayerCellSizes does. 0 when extent has no
// positive coordinate.
double PaperNdtCellSize(const Eigen::Vector3d& extent);

// Builds the single grid of `reference`; *info gets the cell size, dims and
// cell counts (layer = 1). Returns false with *error (and leaves *grid and
// *info unchanged) for invalid options, an empty cloud, non-finite points, a
// cloud whose points all coincide, or a cell size giving too many cells.
bool BuildSingleGrid(const SingleGridOptions& options,
                     const PointCloud& reference,
                     NdtLayer* grid,
                     LayerInfo* info,
                     std::string* error);

}  // namespace mlndt
