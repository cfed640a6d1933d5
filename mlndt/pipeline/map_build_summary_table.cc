#include "mlndt/common/result_table.h"
#include "mlndt/grid/map_memory.h"
#include "mlndt/pipeline/map_builder.h"

namespace mlndt {

const ResultTable& MapBuildSummaryTable() {
  using S = MapBuildSummary;
  static const ResultTable table =
      ResultTableBuilder<S>("MapBuildSummary")
          .Integer("scans", &S::scans, "", "Scans merged.")
          .Integer("input_points",
                   &S::input_points,
                   "",
                   "Finite points read (or given).")
          .IntegerList("scans_without_points",
                       &S::scans_without_points,
                       "Indices of the scans that gave no finite point (all "
                       "NaN, or empty): they add nothing to the map.")
          .Integer("cropped_points",
                   &S::cropped_points,
                   "",
                   "Points removed by the range crop.")
          .Integer("merged_points",
                   &S::merged_points,
                   "",
                   "Points in the merged cloud.")
          .Integer("map_points",
                   &S::map_points,
                   "",
                   "Points after the voxel filter: the map's input.")
          .Struct("memory",
                  &S::memory,
                  MapMemoryEstimateTable(),
                  "The memory of the map build, estimated before it "
                  "(MapMemoryEstimate).")
          .Integer("map_bytes",
                   &S::map_bytes,
                   "bytes",
                   "LayeredGrid::MemoryBytes() of the built map.")
          .Number("read_time_s",
                  &S::read_time_s,
                  "s",
                  "Reading, cropping and moving the scans.")
          .Number("voxel_time_s", &S::voxel_time_s, "s", "The voxel filter.")
          .Number("estimate_time_s",
                  &S::estimate_time_s,
                  "s",
                  "Estimating the memory (EstimateMapMemory).")
          .Number("build_time_s",
                  &S::build_time_s,
                  "s",
                  "Building the map (LayeredGrid::Build).")
          .Number("total_time_s", &S::total_time_s, "s", "The whole build.")
          .Build();
  return table;
}

}  // namespace mlndt
