// mlndt_info: describes point-cloud files, one JSON object per line.
//
//   mlndt_info [--layers [--finest_cell_size_m=0 --num_layers=4 |
//                         --finest_cell_size_m=1.2]
//              [--division_constant=8] [--min_points_per_cell=5]] FILE...
//
// The map flags are the shared ones of LayeredGridOptions (option_flags.h:
// --finest_cell_size_m, --num_layers, ...); the map is the one mlndt_align
// builds from the file as its reference: the library's map options (the
// defaults --help shows) over the points the default range filter keeps
// (range_filter.h). The other registration flags are refused.
//
// For every file:
//   {"schema_version": 2, "tool": "mlndt_info", "version": ..., "command": ...,
//    "file": ..., "format": "PCD", "points": N, "dropped_non_finite": N,
//    "min_m": [x, y, z], "max_m": [x, y, z]}
// (docs/json_schema.md). "points" counts the points kept (finite ones);
// "min_m" and "max_m" are null
// for an empty cloud. With --layers the object also holds "layers": one entry
// per layer of the ML-NDT map (LayeredGrid) built as above, coarsest
// first, with "layer", "cell_size_m", "dims", "occupied_cells",
// "sparse_cells" and "degenerate_cells" (layered_grid.h LayerInfo).
//
// Exit codes: 2 when a file is missing or cannot be opened (checked for
// every file before any is described; nothing is printed) or a flag is
// bad; 1 when a file's contents cannot be read as a cloud or its map cannot
// be built (reported on stderr; the tool goes on with the other files and
// exits with 1 at the end); 0 otherwise.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/range_filter.h"
#include "mlndt/grid/layered_grid.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/json_output.h"
#include "tools/cli/option_flags.h"
#include "tools/cli/tool_main.h"

DEFINE_bool(layers,
            false,
            "Also build the layered NDT map and report its layers");

namespace mlndt {
namespace {

constexpr char kToolName[] = "mlndt_info";

void PrintError(const std::string& message) {
  std::cerr << kToolName << ": " << message << std::endl;
}

bool IsGridFlag(const tools::OptionFlag& flag) {
  return flag.mlndt_path.rfind("grid.", 0) == 0;
}

// The shared flags of LayeredGridOptions' fields (`grid`), or of every
// other option (hidden from --help and refused).
std::vector<std::string> SharedFlags(bool grid) {
  std::vector<std::string> flags;
  for (const tools::OptionFlag& flag : tools::OptionFlags()) {
    if (IsGridFlag(flag) == grid) flags.push_back(flag.name);
  }
  return flags;
}

// Makes `base` the grid flags' defaults (their --help shows them).
void SetGridFlagDefaults(const LayeredGridOptions& base) {
  for (const tools::OptionFlag& flag : tools::OptionFlags()) {
    if (!IsGridFlag(flag)) continue;
    const void* owner = nullptr;
    const OptionField* field = LayeredGridOptionsTable().FindPath(
        flag.mlndt_path.substr(std::string("grid.").size()), &base, &owner);
    gflags::SetCommandLineOptionWithMode(flag.name.c_str(),
                                         field->Format(owner).c_str(),
                                         gflags::SET_FLAGS_DEFAULT);
  }
}

// Map options (the paper's, n = 4) from the shared grid flags given;
// false with *error for bad or contradictory flags, or any other shared
// flag.
bool GridOptionsFromFlags(LayeredGridOptions* grid, std::string* error) {
  for (const std::string& flag : SharedFlags(/*grid=*/true)) {
    if (!FLAGS_layers && tools::FlagGiven(flag)) {
      *error =
          "--num_layers, --division_constant, --finest_cell_size_m, "
          "--min_points_per_cell and the other map flags need --layers";
      return false;
    }
  }
  if (!tools::RefuseGivenFlags(SharedFlags(/*grid=*/false),
                               std::string("does not apply to ") + kToolName +
                                   " (it reads only the map's flags)",
                               error) ||
      !tools::ApplyGivenFlags(
          LayeredGridOptionsTable(), "grid.", false, grid, error)) {
    return false;
  }
  if (!tools::CheckLayerCountFlags(grid->finest_cell_size_m, error)) {
    return false;
  }
  std::string why;
  if (!grid->IsValid(&why)) {
    *error = "invalid map options: " + why;
    return false;
  }
  return true;
}

tools::Json PointJson(const Eigen::Vector3d& point) {
  return {tools::Number(point.x()),
          tools::Number(point.y()),
          tools::Number(point.z())};
}

tools::Json LayersJson(const LayeredGrid& grid) {
  tools::Json layers = tools::Json::array();
  for (const LayerInfo& info : grid.layer_info()) {
    layers.push_back({{"layer", info.layer},
                      {"cell_size_m", tools::Number(info.cell_size_m)},
                      {"dims", {info.dims.x(), info.dims.y(), info.dims.z()}},
                      {"occupied_cells", info.occupied_cells},
                      {"sparse_cells", info.sparse_cells},
                      {"degenerate_cells", info.degenerate_cells}});
  }
  return layers;
}

// Prints the JSON line of one file. Returns false (after reporting on stderr)
// when the file cannot be read or its map cannot be built.
bool DescribeFile(const std::string& path,
                  const LayeredGridOptions& grid_options) {
  PointCloud cloud;
  ReadCloudInfo info;
  std::string error;
  if (!ReadPointCloud(path, &cloud, &info, &error)) {
    // ReadPointCloud's messages start with the path; make sure it is named.
    PrintError(error.find(path) == std::string::npos ? path + ": " + error
                                                     : error);
    return false;
  }

  const Eigen::AlignedBox3d box = BoundingBox(cloud);
  tools::Json json = tools::ToolJson(kToolName);
  json["file"] = path;
  json["format"] = CloudFormatToString(info.format);
  json["points"] = cloud.size();
  json["dropped_non_finite"] = info.dropped_non_finite;
  // An empty cloud has no bounding box.
  json["min_m"] = cloud.empty() ? tools::Json() : PointJson(box.min());
  json["max_m"] = cloud.empty() ? tools::Json() : PointJson(box.max());

  bool ok = true;
  if (FLAGS_layers) {
    RangeFilterSummary dropped;
    const PointCloud kept =
        FilterByRange(RangeFilterOptions(), cloud, &dropped);
    LayeredGrid grid;
    if (LayeredGrid::Build(grid_options, kept, &grid, &error)) {
      json["layers"] = LayersJson(grid);
    } else {
      error = path + ": cannot build the layered map: " + error;
      ok = false;
    }
  }
  std::cout << json.dump(-1, ' ', false, tools::Json::error_handler_t::replace)
            << std::endl;
  if (!ok) PrintError(error);
  return ok;
}

int Run(const std::vector<std::string>& files) {
  LayeredGridOptions grid_options;
  std::string error;
  if (!GridOptionsFromFlags(&grid_options, &error)) {
    PrintError(error);
    return tools::kExitUsage;
  }
  // Every file can be opened before any is described: a missing or
  // unreadable one is bad input (exit 2, nothing printed).
  for (const std::string& file : files) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec) ||
        !std::ifstream(file).good()) {
      PrintError(file + ": no such readable file");
      return tools::kExitUsage;
    }
  }
  bool all_ok = true;
  for (const std::string& file : files) {
    all_ok = DescribeFile(file, grid_options) && all_ok;
  }
  return all_ok ? tools::kExitOk : tools::kExitFailed;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  const char* usage =
      "Prints one JSON line per point-cloud file: format, point count, "
      "bounding box and, with "
      "--layers, the layers of its ML-NDT map.\n"
      "  mlndt_info [--layers [--finest_cell_size_m=1.2 | =0 --num_layers=4]] "
      "FILE...\n"
      "Exit 2 when a FILE is missing or cannot be opened (before any is "
      "described), 1 when one cannot be parsed or its map cannot be built "
      "(the others are still described).";
  mlndt::tools::HideFlagsFromHelp(mlndt::SharedFlags(/*grid=*/false));
  mlndt::SetGridFlagDefaults(mlndt::LayeredGridOptions());
  if (!mlndt::tools::StartTool(usage, false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  if (argc < 2) {
    std::cerr << "mlndt_info: no input files\n"
              << gflags::ProgramUsage() << "\n";
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run(std::vector<std::string>(argv + 1, argv + argc));
}
