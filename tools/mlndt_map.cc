// mlndt_map: builds a layered NDT map of a place and saves it
// (SaveLayeredGrid), or describes a saved map.
//
//   mlndt_map --scans=DIR --poses=poses.txt --output=map.mlndt
//             [--poses_are_camera --calib=calib.txt] [--min_range_m=3
//             --max_range_m=80]
//             [--voxel_size=0.2] [--finest_cell_size_m=2 ...]
//   mlndt_map --scan_list=scans.txt --poses=poses.tum --output=map.mlndt
//   mlndt_map --bag=run.bag --topic=/points --poses=poses.txt --output=...
//   mlndt_map --cloud=merged.pcd --output=map.mlndt [--voxel_size=0.2]
//   mlndt_map info map.mlndt
//
// Building (the default): every scan of --scans (the cloud files in DIR,
// sorted by name), --scan_list (one path per line) or the PointCloud2
// messages of --topic in the ROS 1 bag --bag is read in turn,
// cropped by range from its sensor (--min_range_m, --max_range_m), moved into
// the world frame by its pose and merged; pose k of --poses (KITTI
// 12-number lines or TUM lines, format detected or --poses_format;
// world_from_scan) belongs to scan k; with --poses_are_camera --calib they are
// KITTI camera poses, converted with its Tr line. Or --cloud: one cloud already
// in the world frame. The merged cloud is voxel-filtered (--voxel_size, one
// centroid per voxel) and the map is built with the shared map flags
// (--preset, --finest_cell_size_m, --num_layers, --division_constant,
// --min_points_per_cell, --min_eigenvalue_m2, --min_eigenvalue_ratio,
// --num_threads). The memory a build needs is estimated before anything large
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

#include <cmath>

#include "mlndt/cloud/cloud_format.h"
#include "mlndt/cloud/io.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/pipeline/map_builder.h"
#include "tools/cli/json_output.h"
#include "tools/cli/map_build_flags.h"
#include "tools/cli/map_flags.h"
#include "tools/cli/map_inputs.h"
#include "tools/cli/map_output.h"
#include "tools/cli/output_files.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/scan_input.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_string(scan_list, "", "Text file of scan paths, one a line (relative to the file's folder)");
DEFINE_string(poses, "", "world_from_scan of every scan, in scan order: KITTI (12 numbers a line) "
              "or TUM (t tx ty tz qx qy qz qw) lines");
DEFINE_string(poses_format, "auto", "auto (by extension, then by the first line) | kitti | tum");
DEFINE_string(cloud, "", "One cloud already in the world frame, instead of --scans and --poses");
DEFINE_int32(max_scans, 0, "Use only the first N scans (0 = all)");
DEFINE_double(max_memory_gb, 8.0, "Refuse a build that needs more than this many GB (10^9 bytes) "
              "at once: merged cloud plus working memory (0 = no limit); sets max_memory_bytes");
DEFINE_string(output, "", "The map file to write (SaveLayeredGrid)");
DEFINE_string(output_json, "", "Also write the build's summary as JSON to this file");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_map";

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

int Info(const std::string& path) {
  std::string error;
  if (!tools::RefuseGivenFlags(
          kBuildFlags, "does not apply to 'mlndt_map info'", &error)) {
    return tools::Refuse(kTool, error);
  }
  LayeredGrid map;
  if (!LoadLayeredGrid(path, &map, &error)) return tools::Refuse(kTool, error);
  tools::PrintMapInfo(path, map);
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
  if (!tools::CheckMapSourceFlags(
          from_scans, FLAGS_cloud, FLAGS_poses, error)) {
    return false;
  }
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  if (!tools::RangeFilterOptionsFromFlags(&options->range_filter, error)) {
    return false;
  }
  // --voxel_size (voxel_size_m) and --num_threads (MapBuildOwnOptionsTable).
  if (!tools::MapBuildFlags().Apply(options, error)) return false;
  if (!(FLAGS_max_memory_gb >= 0.0 && FLAGS_max_memory_gb <= 1e6)) {
    *error = "--max_memory_gb must be in [0, 1e6] (0 = no limit)";
    return false;
  }
  options->max_memory_bytes =
      static_cast<size_t>(std::llround(FLAGS_max_memory_gb * 1e9));
  if (!tools::GridOptionsFromFlags(kTool, &options->grid, error)) return false;
  if (!tools::CheckOutputFolderExists("output", FLAGS_output, error) ||
      !tools::CheckOutputFile("output", FLAGS_output, error) ||
      !tools::CheckOutputFile("output_json", FLAGS_output_json, error)) {
    return false;
  }
  CloudFormat cloud_format;
  if (CloudFormatFromPath(FLAGS_output, &cloud_format, error)) {
    *error = "--output=" + FLAGS_output +
             ": a map is not a point cloud: name it .mlndt (every reader "
             "takes a " +
             CloudFormatToString(cloud_format) + " name for a cloud)";
    return false;
  }
  return options->IsValid(error);
}

int Build() {
  MapBuildOptions options;
  std::string error;
  if (!CheckFlags(&options, &error)) return tools::Refuse(kTool, error);

  LayeredGrid map;
  MapBuildSummary summary;
  if (!FLAGS_cloud.empty()) {
    PointCloud cloud;
    if (!ReadPointCloud(FLAGS_cloud, &cloud, nullptr, &error)) {
      return tools::Refuse(kTool, error);
    }
    if (!BuildMapFromCloud(options, std::move(cloud), &map, &summary, &error))
      return tools::Fail(kTool, error);
  } else {
    tools::ScanInput input;
    std::vector<Isometry3d> poses;
    if (!tools::MapScansFromFlags(FLAGS_scans,
                                  FLAGS_scan_list,
                                  FLAGS_poses,
                                  FLAGS_poses_format,
                                  FLAGS_max_scans,
                                  &input,
                                  &poses,
                                  &error)) {
      return tools::Refuse(kTool, error);
    }
    tools::ProgressPrinter progress(kTool, input.names());
    const bool built = BuildMapFromScans(options,
                                         input.names(),
                                         input.Loader(/*allow_empty=*/true),
                                         poses,
                                         &progress,
                                         &map,
                                         &summary,
                                         &error);
    progress.Finish();
    if (!built) return tools::Fail(kTool, error);
    tools::WarnScansWithoutPoints(input, summary);
  }
  if (!SaveLayeredGrid(FLAGS_output, map, &error))
    return tools::Fail(kTool, error);

  tools::PrintMapBuild(options, summary, map);
  std::printf("map written to %s\n", FLAGS_output.c_str());
  if (!FLAGS_output_json.empty()) {
    if (!tools::WriteJsonFile(
            FLAGS_output_json,
            tools::MapBuildJson(FLAGS_output, options, summary, map),
            &error)) {
      return tools::Fail(kTool, error);
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
  // map_inputs.cc refuses --times (a map has no time).
  mlndt::tools::HideFlagsFromHelp({"times"});
  if (!mlndt::tools::StartTool(usage, false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  const auto arguments =
      mlndt::tools::ParseSubcommand("mlndt_map",
                                    argc,
                                    argv,
                                    "info",
                                    1,
                                    "mlndt_map info MAP (one map file)",
                                    "info MAP");
  if (arguments == mlndt::tools::ToolArguments::MISUSE) {
    return mlndt::tools::kExitUsage;
  }
  if (arguments == mlndt::tools::ToolArguments::SUBCOMMAND)
    return mlndt::Info(argv[2]);
  return mlndt::Build();
}
