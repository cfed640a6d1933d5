// mlndt_map: builds a layered NDT map of a place and saves it
// (SaveLayeredGrid), or describes a saved map.
//
//   mlndt_map --scans=DIR --poses=poses.txt --output=map.mlndt
//             [--poses_are_camera --calib=calib.txt] [--min_range=3
//             --max_range=80]
//             [--voxel_size=0.2] [--finest_cell_size=2 ...]
//   mlndt_map --scan_list=scans.txt --poses=poses.tum --output=map.mlndt
//   mlndt_map --bag=run.bag --topic=/points --poses=poses.txt --output=...
//   mlndt_map --cloud=merged.pcd --output=map.mlndt [--voxel_size=0.2]
//   mlndt_map info map.mlndt
//
// Building (the default): every scan of --scans (the cloud files in DIR,
// sorted by name), --scan_list (one path per line) or the PointCloud2
// messages of --topic in the ROS 1 bag --bag is read in turn,
// cropped by range from its sensor (--min_range, --max_range), moved into
// the world frame by its pose and merged; pose k of --poses (KITTI
// 12-number lines or TUM lines, format detected or --poses_format;
// world_from_scan) belongs to scan k; with --poses_are_camera --calib they are
// KITTI camera poses, converted with its Tr line. Or --cloud: one cloud already
// in the world frame. The merged cloud is voxel-filtered (--voxel_size, one
// centroid per voxel) and the map is built with the shared map flags
// (--preset, --finest_cell_size, --num_layers, --division_constant,
// --min_points_per_cell, --min_eigenvalue, --min_eigenvalue_ratio,
// --threads). The memory a build needs is estimated before anything large
// is allocated (mlndt/grid/map_memory.h); a build over --max_memory_gb
// (default 8) is refused with the amount it needs.
//
// `info MAP` prints the map's layers (cell size, grid, occupied cells,
// index, bytes), its cells and bytes in all, its extent and its options.
//
// A map that cannot be used (0 occupied cells, a cell edge or extent that
// is not finite or beyond 1e8 m: grid/map_check.h) is not written. Pose
// files must hold one pose per scan (more poses only with --max_scans);
// a scan without a finite point is named in a warning.
//
// Exit codes: 2 on a bad flag or input found before any work (a pose file
// that is unreadable, holds a non-rigid or 1e300 pose or has the wrong
// count, a missing --scan_list file); 1 when the build fails or its map is
// not usable (nothing written), or an output cannot be written.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <filesystem>
#include <iostream>

#include "mlndt/cloud/io.h"
#include "mlndt/grid/cell_index.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/pipeline/map_builder.h"
#include "tools/common/json_output.h"
#include "tools/common/map_flags.h"
#include "tools/common/map_inputs.h"
#include "tools/common/output_files.h"
#include "tools/common/pose_flags.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/scan_input.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_string(scan_list, "", "Text file of scan paths, one a line (relative to the file's folder)");
DEFINE_string(poses, "", "world_from_scan of every scan, in scan order: KITTI (12 numbers a line) "
              "or TUM (t tx ty tz qx qy qz qw) lines");
DEFINE_string(poses_format, "auto", "auto (by extension, then by the first line) | kitti | tum");
DEFINE_string(cloud, "", "One cloud already in the world frame, instead of --scans and --poses");
DEFINE_int32(max_scans, 0, "Use only the first N scans (0 = all)");
DEFINE_double(voxel_size, 0.0, "Voxel filter of the merged cloud: voxel edge [m], 0 = none, else "
              "in [0.001, 1000]");
DEFINE_double(max_memory_gb, 8.0, "Refuse a build that needs more than this many GB (10^9 bytes) "
              "at once: merged cloud plus working memory (0 = no limit)");
DEFINE_string(output, "", "The map file to write (SaveLayeredGrid)");
DEFINE_string(output_json, "", "Also write the build's summary as JSON to this file");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_map";

int Fail(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitUsage;
}

// The flags of this file (the build's), for refusing them with `info`.
const std::vector<std::string> kBuildFlags = {"scans",
                                              "scan_list",
                                              "bag",
                                              "topic",
                                              "times",
                                              "poses",
                                              "poses_format",
                                              "calib",
                                              "poses_are_camera",
                                              "cloud",
                                              "max_scans",
                                              "min_range_m",
                                              "max_range_m",
                                              "saturated_range_fraction",
                                              "voxel_size",
                                              "max_memory_gb",
                                              "output",
                                              "output_json"};

std::string Vec(const Eigen::Vector3d& v, int precision) {
  return "(" + tools::Fmt(v.x(), precision) + ", " +
         tools::Fmt(v.y(), precision) + ", " + tools::Fmt(v.z(), precision) +
         ")";
}

std::string Dims(const Eigen::Vector3i& d) {
  return std::to_string(d.x()) + " x " + std::to_string(d.y()) + " x " +
         std::to_string(d.z());
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

void PrintExtent(const LayeredGrid& map) {
  const Eigen::AlignedBox3d& b = map.bounds();
  std::printf("extent: %s m, from %s to %s\n",
              Vec(b.sizes(), 2).c_str(),
              Vec(b.min(), 3).c_str(),
              Vec(b.max(), 3).c_str());
}

int Info(const std::string& path) {
  std::string error;
  if (!tools::RefuseGivenFlags(
          kBuildFlags, "does not apply to 'mlndt_map info'", &error)) {
    return Refuse(error);
  }
  LayeredGrid map;
  if (!LoadLayeredGrid(path, &map, &error)) return Refuse(error);
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
  return 0;
}

bool CheckFlags(MapBuildOptions* options, std::string* error) {
  const bool from_scans =
      !FLAGS_scans.empty() || !FLAGS_scan_list.empty() || !FLAGS_bag.empty();
  if (FLAGS_output.empty()) {
    *error =
        "--output=MAP is required. Usage: mlndt_map --scans=DIR "
        "--poses=FILE --output=MAP | --cloud=FILE --output=MAP | info MAP";
    return false;
  }
  if (!from_scans && FLAGS_cloud.empty()) {
    *error =
        "give --scans=DIR (or --scan_list=FILE, or --bag=FILE --topic=NAME) "
        "with --poses, or --cloud";
    return false;
  }
  if (!FLAGS_times.empty()) {
    *error = "--times does not apply to mlndt_map (a map has no time)";
    return false;
  }
  if (from_scans && !FLAGS_cloud.empty()) {
    *error = "give --cloud or --scans/--scan_list/--bag, not both";
    return false;
  }
  if (!FLAGS_cloud.empty() &&
      !tools::RefuseGivenFlags(
          {"poses",
           "poses_format",
           "calib",
           "poses_are_camera",
           "max_scans",
           "min_range_m",
           "max_range_m",
           "saturated_range_fraction"},
          "does not apply to --cloud (one cloud in the world frame, no "
          "sensor origin)",
          error)) {
    return false;
  }
  if (from_scans && FLAGS_poses.empty()) {
    *error =
        "--scans and --scan_list need --poses (world_from_scan of every "
        "scan)";
    return false;
  }
  if (!tools::CheckCameraPoseFlags("--poses", !FLAGS_poses.empty(), error)) {
    return false;
  }
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  if (!tools::RangeFilterOptionsFromFlags(&options->range_filter, error)) {
    return false;
  }
  if (FLAGS_voxel_size != 0.0 &&
      !(FLAGS_voxel_size >= 1e-3 && FLAGS_voxel_size <= 1e3)) {
    *error = "--voxel_size must be 0 (no filter) or in [0.001, 1000] m";
    return false;
  }
  options->voxel_size_m = FLAGS_voxel_size;
  if (!(FLAGS_max_memory_gb >= 0.0 && FLAGS_max_memory_gb <= 1e6)) {
    *error = "--max_memory_gb must be in [0, 1e6] (0 = no limit)";
    return false;
  }
  options->max_memory_bytes =
      static_cast<size_t>(std::llround(FLAGS_max_memory_gb * 1e9));
  if (!tools::GridOptionsFromFlags(kTool, &options->grid, error)) return false;
  options->num_threads = tools::IntFlag("num_threads");
  if (options->num_threads < 1 || options->num_threads > 256) {
    *error = tools::GivenFlagName("num_threads") + " must be in [1, 256]";
    return false;
  }
  const std::filesystem::path folder =
      std::filesystem::absolute(FLAGS_output).parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    *error = "--output=" + FLAGS_output + ": folder " + folder.string() +
             " does not exist";
    return false;
  }
  if (!tools::CheckOutputFile("output", FLAGS_output, error) ||
      !tools::CheckOutputFile("output_json", FLAGS_output_json, error)) {
    return false;
  }
  return options->IsValid(error);
}

// --output_json (docs/json_schema.md, "mlndt_map").
tools::Json SummaryJson(const MapBuildOptions& options,
                        const MapBuildSummary& s,
                        const LayeredGrid& map) {
  tools::Json layers = tools::Json::array();
  for (int i = 1; i <= map.num_layers(); ++i) {
    const NdtLayer& layer = map.layer(i);
    layers.push_back(
        {{"layer", i},
         {"cell_size_m", tools::Number(layer.cell_size())},
         {"dims", {layer.dims().x(), layer.dims().y(), layer.dims().z()}},
         {"occupied_cells", layer.cells().size()},
         {"bytes", layer.MemoryBytes()}});
  }
  const Eigen::Vector3d extent = map.bounds().sizes();
  tools::Json json = tools::ToolJson(kTool);
  json["output"] = FLAGS_output;
  json["scans"] = s.scans;
  json["input_points"] = s.input_points;
  json["cropped_points"] = s.cropped_points;
  json["merged_points"] = s.merged_points;
  json["map_points"] = s.map_points;
  json["min_range_m"] = tools::Number(options.range_filter.min_range_m);
  json["max_range_m"] = tools::Number(options.range_filter.max_range_m);
  json["voxel_size_m"] = tools::Number(options.voxel_size_m);
  json["extent_m"] = {tools::Number(extent.x()),
                      tools::Number(extent.y()),
                      tools::Number(extent.z())};
  json["layers"] = layers;
  json["map_bytes"] = s.map_bytes;
  json["estimate"] = {{"map_bytes", s.memory.map_bytes},
                      {"build_peak_bytes", s.memory.build_peak_bytes},
                      {"cloud_bytes", s.memory.cloud_bytes},
                      {"limit_bytes", options.max_memory_bytes}};
  json["peak_resident_bytes"] = tools::PeakResidentBytes();
  json["time_ms"] = {{"total", tools::Number(s.total_time_s * 1e3)},
                     {"read", tools::Number(s.read_time_s * 1e3)},
                     {"voxel", tools::Number(s.voxel_time_s * 1e3)},
                     {"estimate", tools::Number(s.estimate_time_s * 1e3)},
                     {"build", tools::Number(s.build_time_s * 1e3)}};
  return json;
}

int Build() {
  MapBuildOptions options;
  std::string error;
  if (!CheckFlags(&options, &error)) return Refuse(error);
  bool detect = true;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  if (!tools::ParseTrajectoryFormatFlag(
          "poses_format", FLAGS_poses_format, &detect, &format, &error)) {
    return Refuse(error);
  }

  LayeredGrid map;
  MapBuildSummary summary;
  if (!FLAGS_cloud.empty()) {
    PointCloud cloud;
    if (!ReadPointCloud(FLAGS_cloud, &cloud, nullptr, &error)) {
      return Refuse(error);
    }
    if (!BuildMapFromCloud(options, std::move(cloud), &map, &summary, &error))
      return Fail(error);
  } else {
    tools::ScanInput input;
    const auto list_folder = [](std::vector<std::string>* paths,
                                std::string* list_error) {
      return tools::ScanPathsFromFlags(FLAGS_scans,
                                       FLAGS_scan_list,
                                       {FLAGS_poses, FLAGS_calib},
                                       0,
                                       paths,
                                       list_error);
    };
    if (!tools::ScanInputFromFlags(
            !FLAGS_scans.empty() || !FLAGS_scan_list.empty(),
            list_folder,
            static_cast<size_t>(FLAGS_max_scans),
            &input,
            &error)) {
      return Refuse(error);
    }
    const std::vector<std::string>& paths = input.names();
    std::vector<Isometry3d> poses;
    if (!tools::ReadPoseFile(
            FLAGS_poses, detect, format, FLAGS_calib, &poses, &error)) {
      return Refuse("--poses: " + error);
    }
    // Pose k belongs to scan k: a count that differs (more poses than
    // scans, unless --max_scans cut the scans) means a wrong file or folder.
    if (poses.size() < paths.size() ||
        (poses.size() > paths.size() && FLAGS_max_scans == 0)) {
      return Refuse("--poses=" + FLAGS_poses + " has " +
                    std::to_string(poses.size()) + " poses for " +
                    std::to_string(paths.size()) +
                    " scans (pose k belongs to scan k; use --max_scans to "
                    "take the first scans of a longer run)");
    }
    tools::Progress progress(kTool, paths.size());
    const bool ok = BuildMapFromScans(
        options,
        paths,
        input.Loader(/*allow_empty=*/true),
        poses,
        [&](size_t done, size_t) {
          progress.Update(
              done, std::filesystem::path(paths[done - 1]).filename().string());
        },
        &map,
        &summary,
        &error);
    progress.Finish();
    if (!ok) return Fail(error);
    for (const size_t k : summary.scans_without_points) {
      std::cerr << kTool << ": warning: scan " << k << " ("
                << (input.from_bag() ? paths[k] : input.paths()[k])
                << ") has no finite point (all NaN or empty): it adds "
                   "nothing to the map\n";
    }
  }
  if (!SaveLayeredGrid(FLAGS_output, map, &error)) return Fail(error);

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
      FormatBytes(tools::PeakResidentBytes()).c_str(),
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
  std::printf("map written to %s\n", FLAGS_output.c_str());
  if (!FLAGS_output_json.empty()) {
    if (!tools::WriteJsonFile(
            FLAGS_output_json, SummaryJson(options, summary, map), &error)) {
      return Fail(error);
    }
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  const char* usage =
      "Builds a layered NDT map from scans and poses (or one cloud), or "
      "describes one.\n"
      "  mlndt_map --scans=DIR --poses=FILE [--poses_are_camera --calib=FILE] "
      "--output=MAP\n"
      "  mlndt_map --cloud=FILE --output=MAP\n"
      "  mlndt_map info MAP";
  mlndt::tools::HideFlagsFromHelp(mlndt::tools::MapBuildRefusedFlags());
  if (!mlndt::tools::StartTool(usage, false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  if (argc > 1 && std::string(argv[1]) == "info") {
    if (argc != 3) {
      std::cerr << "mlndt_map: usage: mlndt_map info MAP (one map file)\n";
      return mlndt::tools::kExitUsage;
    }
    return mlndt::Info(argv[2]);
  }
  if (argc > 1) {
    std::cerr << "mlndt_map: unexpected argument '" << argv[1]
              << "' (flags are --name=value; the one subcommand is 'info "
                 "MAP')\n";
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Build();
}
