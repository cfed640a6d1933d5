#include "tools/cli/map_output.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "lab/report/text_format.h"
#include "mlndt/grid/cell_index.h"
#include "mlndt/grid/map_memory.h"
#include "tools/cli/result_json.h"
#include "tools/cli/tool_utils.h"

namespace mlndt {
namespace tools {
namespace {

std::string Vec(const Eigen::Vector3d& v, int precision) {
  return "(" + Fmt(v.x(), precision) + ", " + Fmt(v.y(), precision) + ", " +
         Fmt(v.z(), precision) + ")";
}

std::string Dims(const Eigen::Vector3i& d) {
  return std::to_string(d.x()) + " x " + std::to_string(d.y()) + " x " +
         std::to_string(d.z());
}

// "extent: (x, y, z) m, from (..) to (..)".
void PrintExtent(const LayeredGrid& map) {
  const Eigen::AlignedBox3d& b = map.bounds();
  std::printf("extent: %s m, from %s to %s\n",
              Vec(b.sizes(), 2).c_str(),
              Vec(b.min(), 3).c_str(),
              Vec(b.max(), 3).c_str());
}

// The layer table shared by the build report and `info`.
void PrintLayers(const LayeredGrid& map) {
  std::printf("%-5s %10s %20s %14s %10s %7s %12s\n",
              "layer",
              "cell [m]",
              "grid",
              "grid cells",
              "occupied",
              "index",
              "bytes");
  size_t cells = 0;
  for (int i = 1; i <= map.num_layers(); ++i) {
    const NdtLayer& layer = map.layer(i);
    const bool dense = layer.num_grid_cells() <= CellIndex::kMaxDenseCells;
    std::printf("%-5d %10.4f %20s %14lld %10zu %7s %12zu\n",
                i,
                layer.cell_size(),
                Dims(layer.dims()).c_str(),
                static_cast<long long>(layer.num_grid_cells()),
                layer.cells().size(),
                dense ? "dense" : "hash",
                layer.MemoryBytes());
    cells += layer.cells().size();
  }
  std::printf("cells: %zu over %d layers, map bytes %zu (%s)\n",
              cells,
              map.num_layers(),
              map.MemoryBytes(),
              FormatBytes(static_cast<double>(map.MemoryBytes())).c_str());
}

}  // namespace

void PrintMapInfo(const std::string& path, const LayeredGrid& map) {
  std::error_code ec;
  const auto file_bytes = std::filesystem::file_size(path, ec);
  std::printf("map: %s (%llu bytes on disk)\n",
              path.c_str(),
              static_cast<unsigned long long>(ec ? 0 : file_bytes));
  std::printf("points: %zu\n", map.num_points());
  PrintExtent(map);
  const LayeredGridOptions& o = map.options();
  std::printf(
      "options: q = %d, min points per cell %d, eigenvalues >= %g x largest "
      "and >= %g m^2\n",
      o.division_constant,
      o.min_points_per_cell,
      o.regularization.min_eigenvalue_ratio,
      o.regularization.min_eigenvalue_m2);
  PrintLayers(map);
}

void PrintMapBuild(const MapBuildOptions& options,
                   const MapBuildSummary& summary,
                   const LayeredGrid& map) {
  std::printf(
      "scans: %zu, points: %zu read, %zu cropped, %zu merged, %zu after the "
      "voxel filter\n",
      summary.scans,
      summary.input_points,
      summary.cropped_points,
      summary.merged_points,
      summary.map_points);
  PrintExtent(map);
  PrintLayers(map);
  std::printf(
      "memory: estimated map %s (built %s), build peak %s + cloud %s; peak "
      "resident %s (limit %s)\n",
      FormatBytes(double(summary.memory.map_bytes)).c_str(),
      FormatBytes(double(summary.map_bytes)).c_str(),
      FormatBytes(double(summary.memory.build_peak_bytes)).c_str(),
      FormatBytes(double(summary.memory.cloud_bytes)).c_str(),
      FormatBytes(PeakResidentBytes()).c_str(),
      options.max_memory_bytes > 0
          ? FormatBytes(double(options.max_memory_bytes)).c_str()
          : "none");
  std::printf(
      "time [s]: read %.3f, voxel filter %.3f, estimate %.3f, build %.3f, "
      "total %.3f\n",
      summary.read_time_s,
      summary.voxel_time_s,
      summary.estimate_time_s,
      summary.build_time_s,
      summary.total_time_s);
}

void WarnScansWithoutPoints(const ScanInput& input,
                            const MapBuildSummary& summary) {
  for (const size_t k : summary.scans_without_points) {
    std::cerr << "mlndt_map: warning: scan " << k << " ("
              << (input.from_bag() ? input.names()[k] : input.paths()[k])
              << ") has no finite point (all NaN or empty): it adds "
                 "nothing to the map\n";
  }
}

Json MapBuildJson(const std::string& output,
                  const MapBuildOptions& options,
                  const MapBuildSummary& s,
                  const LayeredGrid& map) {
  Json json = ToolJson("mlndt_map");
  json["output"] = output;
  json.update(ResultJsonOf(MapBuildSummaryTable(), s));
  json["min_range_m"] = Number(options.range_filter.min_range_m);
  json["max_range_m"] = Number(options.range_filter.max_range_m);
  json["voxel_size_m"] = Number(options.voxel_size_m);
  json["max_memory_bytes"] = options.max_memory_bytes;
  const Eigen::Vector3d extent = map.bounds().sizes();
  json["extent_m"] = {
      Number(extent.x()), Number(extent.y()), Number(extent.z())};
  json["layers"] = Json::array();
  for (int i = 1; i <= map.num_layers(); ++i) {
    const NdtLayer& layer = map.layer(i);
    json["layers"].push_back(
        {{"layer", i},
         {"cell_size_m", Number(layer.cell_size())},
         {"dims", {layer.dims().x(), layer.dims().y(), layer.dims().z()}},
         {"occupied_cells", layer.cells().size()},
         {"bytes", layer.MemoryBytes()}});
  }
  json["peak_resident_bytes"] = PeakResidentBytes();
  return json;
}

}  // namespace tools
}  // namespace mlndt
