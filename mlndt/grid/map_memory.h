#pragma once

// How much memory the layered map of a cloud will take, found before it is
// built: the layer geometry LayeredGrid::Build would choose (layered_grid.h)
// and the cells the points fall into, counted in one pass per layer with
// small tables (a CellIndex plus 12 bytes a touched cell; coarse layers of a
// nesting q are counted from the finer layer's cells). From these come
//
//  * map_bytes: LayeredGrid::MemoryBytes() of the finished map, exact except
//    that cells later found degenerate (no usable covariance) are counted as
//    kept, so it is an upper bound;
//  * build_peak_bytes: the largest heap the build holds at once besides the
//    input cloud: per point a key and a slot (12 bytes) while the finest
//    layer is binned, per touched cell its moments (104 bytes), a candidate
//    NdtCell (248 bytes) and the index while a layer is finished, plus the
//    layers already finished. It models layered_grid.cc's buffers (vector
//    capacities included) and is checked against the measured peak in
//    docs/maps.md.
//
// With a limit, the work stops as soon as the cloud plus what is certain to
// be needed exceeds it: first a bound from the geometry alone (the point
// buffers and dense tables), then the counting pass's own tables, then the
// full estimate, so that a map that cannot fit is refused before anything
// large is allocated.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/result_table.h"
#include "mlndt/grid/layered_grid.h"

namespace mlndt {

struct LayerMemoryEstimate {
  int layer = 0;  // 1-based, 1 the coarsest.
  double cell_size_m = 0.0;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();
  int64_t grid_cells = 0;    // dims.prod().
  bool dense_index = false;  // CellIndex table of 4 bytes a grid cell.
  size_t touched_cells = 0;  // Cells holding at least one point.
  size_t kept_cells = 0;     // Cells with >= min_points_per_cell points.
  size_t bytes = 0;          // NdtLayer::MemoryBytes() of the layer.
};

struct MapMemoryEstimate {
  std::vector<LayerMemoryEstimate> layers;  // layers[i - 1] is layer i.
  size_t cloud_bytes = 0;                   // The input cloud's point vector.
  size_t map_bytes = 0;         // LayeredGrid::MemoryBytes() (upper bound).
  size_t build_peak_bytes = 0;  // Build's peak heap besides the cloud.
  size_t counting_bytes = 0;    // Peak of the counting pass itself.
  // True when every layer was counted (false when a limit stopped it
  // before; the byte fields then hold the lower bound that was exceeded).
  bool complete = false;
  // True when the estimate was refused because the build would exceed the
  // limit (false when it was refused for the cloud or the options).
  bool exceeds_limit = false;

  // The cloud plus the build's peak: what the process needs to build.
  size_t total_bytes() const { return cloud_bytes + build_peak_bytes; }
};

// MapMemoryEstimate's fields (result_table.h), LayerMemoryEstimate's
// nested: the estimate in mlndt_map's JSON and docs/json_schema.md.
const ResultTable& MapMemoryEstimateTable();

// Estimates the memory of LayeredGrid::Build(options, cloud). With
// max_total_bytes > 0, returns false with *error (saying how much is needed
// and naming the limit) as soon as total_bytes() is known to exceed it; the
// counting pass itself is refused first when its tables alone would.
// Returns false with *error, like Build, for invalid options, an empty
// cloud, non-finite points, coincident points, or too many layers or cells.
bool EstimateMapMemory(const LayeredGridOptions& options,
                       const PointCloud& cloud,
                       size_t max_total_bytes,
                       MapMemoryEstimate* estimate,
                       std::string* error);

// "1.23 GB" (10^9 bytes), "456.7 MB", "12.3 kB", "512 B", for messages.
std::string FormatBytes(double bytes);

}  // namespace mlndt
