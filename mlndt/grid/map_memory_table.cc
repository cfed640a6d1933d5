#include "mlndt/common/result_table.h"
#include "mlndt/grid/map_memory.h"

namespace mlndt {
namespace {

const ResultTable& LayerMemoryEstimateTable() {
  using L = LayerMemoryEstimate;
  static const ResultTable table =
      ResultTableBuilder<L>("LayerMemoryEstimate")
          .Integer("layer", &L::layer, "", "1-based, 1 the coarsest.")
          .Number("cell_size_m", &L::cell_size_m, "m", "The layer's cell edge.")
          .Computed("dims",
                    ResultType::INTEGER_LIST,
                    "",
                    "Grid cells per axis (x, y, z).",
                    [](const L& l) {
                      return ResultValue(std::vector<int64_t>(
                          {l.dims.x(), l.dims.y(), l.dims.z()}));
                    })
          .Integer("grid_cells", &L::grid_cells, "", "dims' product.")
          .Bool("dense_index",
                &L::dense_index,
                "The cell index is a table of 4 bytes a grid cell (else a "
                "hash).")
          .Integer("touched_cells",
                   &L::touched_cells,
                   "",
                   "Cells holding at least one point.")
          .Integer("kept_cells",
                   &L::kept_cells,
                   "",
                   "Cells with at least min_points_per_cell points.")
          .Integer("bytes", &L::bytes, "bytes", "NdtLayer::MemoryBytes().")
          .Build();
  return table;
}

}  // namespace

const ResultTable& MapMemoryEstimateTable() {
  using E = MapMemoryEstimate;
  static const ResultTable table =
      ResultTableBuilder<E>("MapMemoryEstimate")
          .StructList("layers",
                      &E::layers,
                      LayerMemoryEstimateTable(),
                      "One estimate per layer, layer 1 first.")
          .Integer("cloud_bytes",
                   &E::cloud_bytes,
                   "bytes",
                   "The input cloud's point vector.")
          .Integer("map_bytes",
                   &E::map_bytes,
                   "bytes",
                   "LayeredGrid::MemoryBytes() of the map (an upper bound).")
          .Integer("build_peak_bytes",
                   &E::build_peak_bytes,
                   "bytes",
                   "The build's peak heap besides the cloud.")
          .Integer("counting_bytes",
                   &E::counting_bytes,
                   "bytes",
                   "The peak of the counting pass itself.")
          .Bool("complete",
                &E::complete,
                "Every layer was counted (else a limit stopped it and the "
                "bytes are the lower bound that was exceeded).")
          .Bool("exceeds_limit",
                &E::exceeds_limit,
                "Refused because the build would exceed the limit.")
          .Build();
  return table;
}

}  // namespace mlndt
