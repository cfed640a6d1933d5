// mlndt_localize: registers every scan of a folder (or a list file) onto a
// saved layered map (mlndt_map) with ML-NDT, one scan at a time.
//
//   mlndt_localize --map=map.mlndt (--scans=DIR [--times=FILE]
//                  | --bag=FILE --topic=NAME) --output_dir=OUT
//                  [--initial_guess=tx,ty,tz,a,b,g | --initial_matrix=...
//                   | --initial_poses=FILE [--poses_are_camera
//                   --calib=calib.txt]]
//                  [--motion_model=constant_velocity|constant_pose]
//                  [--plots=false] [any registration flag of mlndt_align]
//
// The first scan starts from --initial_guess (metres and degrees, R = Rx Ry
// Rz), --initial_matrix (12 numbers, row-major 3x4) or the first pose of
// --initial_poses (KITTI or TUM; with --poses_are_camera --calib KITTI camera
// poses), else the identity; map_from_scan. Each next scan starts from the
// previous pose moved by the last relative motion (constant velocity; Localizer
// in mlndt/pipeline/localizer.h). The map and the current scan are the only
// clouds in memory: each scan is read when its turn comes.
//
// Scans come from a folder, a --scan_list or a ROS 1 bag's PointCloud2
// topic (tools/common/scan_input.h).
//
// Writes into --output_dir: trajectory_kitti.txt and trajectory_tum.txt
// (map_from_scan of every scan; TUM time stamps are the bag's header stamps
// or the --times file's, else the scan indices, as the file's first line
// says),
// scans.csv (per scan: verdict, fit quality, pose, correction from the
// prediction, times), summary.json, and with --plots (default) the top view
// trajectory_xy.png of the map's finest cells (subsampled to
// --plot_max_cells) and the trajectory (gnuplot; data and script in
// plot_data/). The summary counts the scans by verdict (CONVERGENCE,
// NO_CONVERGENCE, LOW_QUALITY, DEGENERATE, FAILURE); only CONVERGENCE and
// NO_CONVERGENCE are usable (IsUsableTermination), the others keep their
// prediction as their pose.
//
// Exit codes: 2 on a bad flag or input refused before any work; 1 when any
// scan's result is not usable (every file is still written), a scan cannot
// be read, an output cannot be written, or plots were requested but
// gnuplot is missing (the other files are still written); 0 when every
// scan has a usable pose.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "lab/eval/statistics.h"
#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/grid/map_memory.h"
#include "mlndt/pipeline/localizer.h"
#include "tools/common/gnuplot.h"
#include "tools/common/json_output.h"
#include "tools/common/map_flags.h"
#include "tools/common/map_inputs.h"
#include "tools/common/output_files.h"
#include "tools/common/pose_flags.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/scan_input.h"
#include "tools/common/start_layer_check.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"
#include "tools/common/verdict_counts.h"

// clang-format off
DEFINE_string(map, "", "The map file (mlndt_map --output)");
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_string(scan_list, "", "Text file of scan paths, one a line (relative to the file's folder)");
DEFINE_int32(max_scans, 0, "Localise only the first N scans (0 = all)");
DEFINE_string(initial_guess, "", "First scan's map_from_scan: tx,ty,tz,alpha,beta,gamma (m, deg, "
              "R = Rx Ry Rz)");
DEFINE_string(initial_matrix, "", "First scan's map_from_scan: 12 comma-separated numbers "
              "(row-major 3x4)");
DEFINE_string(initial_poses, "", "Pose file (KITTI or TUM) whose first pose is the first scan's "
              "map_from_scan");
DEFINE_string(initial_poses_format, "auto", "auto | kitti | tum");
DEFINE_string(motion_model, "constant_velocity",
              "Initial guess of scan k > 0: constant_velocity (previous pose x last motion) | "
              "constant_pose (previous pose)");
DEFINE_string(output_dir, "", "Folder for the trajectories, scans.csv, summary.json and the plot");
DEFINE_bool(plots, true, "Write trajectory_xy.png with gnuplot (exit 1 when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
DEFINE_int32(plot_max_cells, 20000, "Finest-layer cell means drawn in the top view (subsampled), "
             ">= 0");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_localize";

int Fail(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitUsage;
}

// Every flag is checked here, before the map or any scan is read.
bool CheckFlags(LocalizerOptions* options,
                tools::ScanInput* input,
                std::string* error) {
  if (FLAGS_map.empty() || FLAGS_output_dir.empty() ||
      (FLAGS_scans.empty() && FLAGS_scan_list.empty() && FLAGS_bag.empty())) {
    *error =
        "give --map=FILE, --scans=DIR (or --scan_list=FILE, or --bag=FILE "
        "--topic=NAME) and "
        "--output_dir=DIR. Usage: mlndt_localize --map=map.mlndt --scans=DIR "
        "--output_dir=OUT [--initial_guess=tx,ty,tz,a,b,g]";
    return false;
  }
  if (!std::filesystem::is_regular_file(FLAGS_map)) {
    *error = "--map=" + FLAGS_map +
             (std::filesystem::is_directory(FLAGS_map)
                  ? ": it is a directory (give the map file mlndt_map wrote)"
                  : ": no such file");
    return false;
  }
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  if (FLAGS_plot_max_cells < 0) {
    *error = "--plot_max_cells must be >= 0";
    return false;
  }
  const int given = !FLAGS_initial_guess.empty() +
                    !FLAGS_initial_matrix.empty() +
                    !FLAGS_initial_poses.empty();
  if (given > 1) {
    *error =
        "give one of --initial_guess, --initial_matrix and --initial_poses";
    return false;
  }
  if (!tools::CheckCameraPoseFlags(
          "--initial_poses", !FLAGS_initial_poses.empty(), error)) {
    return false;
  }
  if (!StringToMotionModel(FLAGS_motion_model, &options->motion_model)) {
    *error = "--motion_model=" + FLAGS_motion_model +
             ": expected constant_velocity or constant_pose";
    return false;
  }
  if (!tools::RefuseMapFlags(kTool, error) ||
      !tools::RegistrationOptionsFromFlags(&options->registration, error)) {
    return false;
  }
  if (!options->IsValid(error)) return false;
  const auto list_folder = [](std::vector<std::string>* paths,
                              std::string* list_error) {
    return tools::ScanPathsFromFlags(
        FLAGS_scans,
        FLAGS_scan_list,
        {FLAGS_map, FLAGS_initial_poses, FLAGS_calib, FLAGS_times},
        0,
        paths,
        list_error);
  };
  return tools::ScanInputFromFlags(
      !FLAGS_scans.empty() || !FLAGS_scan_list.empty(),
      list_folder,
      static_cast<size_t>(FLAGS_max_scans),
      input,
      error);
}

bool FirstPose(Isometry3d* map_from_scan, std::string* error) {
  bool given = false;
  if (!tools::ParseInitialPose(FLAGS_initial_guess,
                               FLAGS_initial_matrix,
                               map_from_scan,
                               &given,
                               error)) {
    return false;
  }
  if (FLAGS_initial_poses.empty()) return true;
  bool detect = true;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  std::vector<Isometry3d> poses;
  if (!tools::ParseTrajectoryFormatFlag("initial_poses_format",
                                        FLAGS_initial_poses_format,
                                        &detect,
                                        &format,
                                        error) ||
      !tools::ReadPoseFile(
          FLAGS_initial_poses, detect, format, FLAGS_calib, &poses, error)) {
    *error = "--initial_poses: " + *error;
    return false;
  }
  *map_from_scan = poses.front();
  return true;
}

// tx, ty, tz [m], alpha, beta, gamma [deg] of a pose (R = Rx Ry Rz).
std::vector<double> PoseNumbers(const Isometry3d& pose) {
  const Vector6d xi = IsometryToPoseVector(pose);
  std::vector<double> v(xi.data(), xi.data() + 6);
  for (int a = 3; a < 6; ++a) v[static_cast<size_t>(a)] *= kRadToDeg;
  return v;
}

std::string PoseColumns(const Isometry3d& pose) {
  std::string out;
  for (const double v : PoseNumbers(pose)) {
    out += (out.empty() ? "" : ",") + tools::Num(v);
  }
  return out;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool WriteScansCsv(const std::string& path,
                   const std::vector<std::string>& files,
                   const std::vector<LocalizationResult>& results,
                   std::string* error) {
  std::ostringstream out;
  out << "index,file,termination,iterations,input_points,sampled_points,"
         "matched_points,score,own_cell_fraction,inlier_fraction,mean_score,"
         "median_distance,tx_m,ty_m,tz_m,alpha_deg,beta_deg,gamma_deg,"
         "correction_m,correction_deg,load_ms,sampling_ms,solve_ms,"
         "registration_ms,message\n";
  for (const LocalizationResult& r : results) {
    out << r.index << ","
        << CsvField(std::filesystem::path(files[r.index]).filename().string())
        << "," << TerminationTypeToString(r.termination_type) << ","
        << r.iterations << "," << r.input_points << "," << r.sampled_points
        << "," << r.matched_points << "," << tools::Num(r.final_score) << ","
        << tools::Num(r.quality.own_cell_fraction) << ","
        << tools::Num(r.quality.inlier_fraction) << ","
        << tools::Num(r.quality.mean_score) << ","
        << tools::Num(r.quality.median_distance) << ","
        << PoseColumns(r.map_from_scan) << ","
        << tools::Num(
               TranslationErrorM(r.predicted_map_from_scan, r.map_from_scan))
        << ","
        << tools::Num(
               RotationErrorRad(r.predicted_map_from_scan, r.map_from_scan) *
               kRadToDeg)
        << "," << tools::Num(r.load_time_s * 1e3) << ","
        << tools::Num(r.sampling_time_s * 1e3) << ","
        << tools::Num(r.solve_time_s * 1e3) << ","
        << tools::Num(r.registration_time_s * 1e3) << "," << CsvField(r.message)
        << "\n";
  }
  return WriteFileAtomically(path, out.str(), error);
}

// summary.json (docs/json_schema.md, "mlndt_localize").
tools::Json SummaryJson(const LocalizerOptions& options,
                        const LayeredGrid& map,
                        const Isometry3d& first_guess,
                        const std::vector<LocalizationResult>& results,
                        double map_load_s,
                        double total_s) {
  tools::VerdictCounts verdicts;
  std::vector<double> registration_ms, inliers, own;
  for (const LocalizationResult& r : results) {
    verdicts.Add(r.termination_type);
    registration_ms.push_back(r.registration_time_s * 1e3);
    inliers.push_back(r.quality.inlier_fraction);
    own.push_back(r.quality.own_cell_fraction);
  }
  size_t cells = 0;
  for (int i = 1; i <= map.num_layers(); ++i) {
    cells += map.layer(i).cells().size();
  }
  tools::Json json = tools::ToolJson(kTool);
  json["map"] = FLAGS_map;
  json["map_info"] = {{"layers", map.num_layers()},
                      {"cells", cells},
                      {"bytes", map.MemoryBytes()},
                      {"finest_cell_size_m",
                       tools::Number(map.layer(map.num_layers()).cell_size())}};
  json["scans"] = results.size();
  json["motion_model"] = MotionModelToString(options.motion_model);
  json["backend"] = BackendTypeToString(options.registration.backend.type);
  json["first_guess"] = tools::PoseJson(first_guess);
  json["terminations"] = verdicts.ToJson();
  json["usable"] = verdicts.usable();
  json["unusable"] = verdicts.unusable();
  json["unusable_pose"] =
      "the prediction (dead reckoning): LOW_QUALITY, DEGENERATE and FAILURE "
      "scans are not to be used";
  json["inlier_fraction"] = tools::StatsJson(ComputeStats(inliers));
  json["own_cell_fraction"] = tools::StatsJson(ComputeStats(own));
  json["time_ms"] = {{"total", tools::Number(total_s * 1e3)},
                     {"map_load", tools::Number(map_load_s * 1e3)}};
  json["time_ms_stats"] = {
      {"registration", tools::StatsJson(ComputeStats(registration_ms))}};
  json["peak_resident_bytes"] = tools::PeakResidentBytes();
  return json;
}

// trajectory_xy.png: the finest layer's cell means (every k-th, at most
// --plot_max_cells) and the trajectory, seen from above.
bool WritePlot(const std::string& dir,
               const LayeredGrid& map,
               const std::vector<LocalizationResult>& results,
               std::string* error) {
  const std::string data_dir = dir + "/plot_data";
  std::error_code ec;
  std::filesystem::create_directories(data_dir, ec);
  if (ec) {
    *error = data_dir + ": " + ec.message();
    return false;
  }
  const std::vector<NdtCell>& cells = map.layer(map.num_layers()).cells();
  const size_t max_cells = static_cast<size_t>(FLAGS_plot_max_cells);
  const size_t stride =
      max_cells == 0
          ? 0
          : std::max<size_t>(1, (cells.size() + max_cells - 1) / max_cells);
  {
    std::ostringstream out;
    out << "# x_m y_m z_m (finest-layer cell means, every " << stride
        << "-th)\n";
    for (size_t c = 0; stride > 0 && c < cells.size(); c += stride) {
      out << cells[c].mean.x() << " " << cells[c].mean.y() << " "
          << cells[c].mean.z() << "\n";
    }
    std::ostringstream trajectory;
    trajectory << "# x_m y_m converged(1/0)\n";
    for (const LocalizationResult& r : results) {
      trajectory << r.map_from_scan.translation().x() << " "
                 << r.map_from_scan.translation().y() << " "
                 << (r.termination_type == TerminationType::CONVERGENCE)
                 << "\n";
    }
    if (!WriteFileAtomically(data_dir + "/map_cells.dat", out.str(), error) ||
        !WriteFileAtomically(
            data_dir + "/trajectory.dat", trajectory.str(), error)) {
      return false;
    }
  }
  std::ostringstream script;
  const std::string png = dir + "/trajectory_xy.png";
  script << tools::GnuplotPngHeader(1000, 800) << tools::GnuplotSetOutput(png)
         << "set title 'Map (finest cell means) and trajectory, top view'\n"
         << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\n"
         << "plot " << tools::GnuplotQuote(data_dir + "/map_cells.dat")
         << " using 1:2 with points pt 7 ps 0.3 lc rgb '#a0a0a0' title 'map "
            "cells', "
         << tools::GnuplotQuote(data_dir + "/trajectory.dat")
         << " using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#c00000' "
            "title 'trajectory'\n";
  return tools::RunGnuplot(
      FLAGS_gnuplot, data_dir + "/plot.gp", script.str(), {png}, error);
}

int Run() {
  const double start = NowSeconds();
  LocalizerOptions options;
  tools::ScanInput input;
  std::string error;
  if (!CheckFlags(&options, &input, &error)) return Refuse(error);
  const std::vector<std::string>& paths = input.names();
  Isometry3d first_guess;
  if (!FirstPose(&first_guess, &error)) return Refuse(error);
  LayeredGrid map;
  if (!LoadLayeredGrid(FLAGS_map, &map, &error)) return Refuse(error);
  // The library would clamp a start layer beyond the map's layers.
  if (!tools::CheckStartLayerForMap(
          options.registration.schedule, map.num_layers(), &error)) {
    return Refuse(error);
  }
  const double map_load_s = NowSeconds() - start;
  if (!tools::PrepareOutputDir("output_dir",
                               FLAGS_output_dir,
                               {"scans.csv",
                                "summary.json",
                                "trajectory_kitti.txt",
                                "trajectory_tum.txt"},
                               &error)) {
    return Refuse(error);
  }
  const bool gnuplot_ok =
      !FLAGS_plots || tools::GnuplotAvailable(FLAGS_gnuplot);
  if (!gnuplot_ok) {
    std::cerr << kTool << ": gnuplot ('" << FLAGS_gnuplot
              << "') not found: the plot will be skipped (install "
                 "gnuplot-nox, or pass --plots=false)\n";
  }

  std::printf("map: %s, %d layers, finest cell %.3f m, %s\n",
              FLAGS_map.c_str(),
              map.num_layers(),
              map.layer(map.num_layers()).cell_size(),
              FormatBytes(static_cast<double>(map.MemoryBytes())).c_str());

  tools::Progress progress(kTool, paths.size());
  const ScanLoader load = input.Loader();
  const LocalizationCallback report = [&](const LocalizationResult& r) {
    char detail[200];
    std::snprintf(detail,
                  sizeof(detail),
                  "%s %s, inliers %.3f, %d it, %.0f ms",
                  std::filesystem::path(paths[r.index]).filename().c_str(),
                  TerminationTypeToString(r.termination_type),
                  r.quality.inlier_fraction,
                  r.iterations,
                  r.registration_time_s * 1e3);
    progress.Update(r.index + 1, detail);
  };
  std::vector<LocalizationResult> results;
  const bool ok = LocalizeScans(
      options, map, first_guess, paths.size(), load, report, &results, &error);
  progress.Finish();
  if (!ok) return Fail(error);

  const std::string out = FLAGS_output_dir + "/";
  Trajectory trajectory;
  for (const LocalizationResult& r : results) {
    trajectory.Add(input.StampOf(r.index), r.map_from_scan);
  }
  if (!WriteTrajectory(out + "trajectory_kitti.txt",
                       TrajectoryFormat::KITTI,
                       trajectory,
                       &error) ||
      !WriteTrajectory(out + "trajectory_tum.txt",
                       TrajectoryFormat::TUM,
                       trajectory,
                       input.TumComment(),
                       &error) ||
      !WriteScansCsv(out + "scans.csv", paths, results, &error)) {
    return Fail(error);
  }
  if (!tools::WriteJsonFile(out + "summary.json",
                            SummaryJson(options,
                                        map,
                                        first_guess,
                                        results,
                                        map_load_s,
                                        NowSeconds() - start),
                            &error)) {
    return Fail(error);
  }

  std::printf("%-5s %-24s %-15s %5s %8s %8s %10s %10s %10s %9s %9s\n",
              "scan",
              "file",
              "termination",
              "iters",
              "own",
              "inliers",
              "x [m]",
              "y [m]",
              "yaw [deg]",
              "load [ms]",
              "reg [ms]");
  std::vector<double> registration_ms;
  tools::VerdictCounts verdicts;
  for (const LocalizationResult& r : results) {
    const Vector6d xi = IsometryToPoseVector(r.map_from_scan);
    std::printf(
        "%-5zu %-24s %-15s %5d %8.3f %8.3f %10.3f %10.3f %10.3f %9.1f "
        "%9.1f\n",
        r.index,
        std::filesystem::path(paths[r.index]).filename().c_str(),
        TerminationTypeToString(r.termination_type),
        r.iterations,
        r.quality.own_cell_fraction,
        r.quality.inlier_fraction,
        xi(0),
        xi(1),
        xi(5) * kRadToDeg,
        r.load_time_s * 1e3,
        r.registration_time_s * 1e3);
    registration_ms.push_back(r.registration_time_s * 1e3);
    verdicts.Add(r.termination_type);
  }
  const Stats t = ComputeStats(registration_ms);
  std::printf(
      "scans: %zu, usable %zu (%s); registration [ms]: mean %.1f, median "
      "%.1f, max %.1f; peak memory %s\n",
      results.size(),
      verdicts.usable(),
      verdicts.Line().c_str(),
      t.mean,
      t.median,
      t.max,
      FormatBytes(tools::PeakResidentBytes()).c_str());
  std::printf("output: %s\n", FLAGS_output_dir.c_str());
  if (FLAGS_plots) {
    if (!gnuplot_ok) {
      return Fail("plot skipped: gnuplot ('" + FLAGS_gnuplot +
                  "') not found; the other outputs are written. Install "
                  "gnuplot-nox or pass --plots=false");
    }
    if (!WritePlot(FLAGS_output_dir, map, results, &error)) return Fail(error);
    std::printf("plot: trajectory_xy.png\n");
  }
  if (verdicts.unusable() > 0) {
    return Fail(std::to_string(verdicts.unusable()) + " of " +
                std::to_string(verdicts.total()) +
                " scans have no usable pose (" + verdicts.Line() +
                "): their poses in the trajectories are the predictions; "
                "see the termination column of scans.csv");
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  const char* usage =
      "Registers every scan of a folder onto a saved map (mlndt_map).\n"
      "  mlndt_localize --map=map.mlndt --scans=DIR --output_dir=OUT "
      "[--initial_guess=tx,ty,tz,a,b,g]\n"
      "Exit 1 when any scan's result is not usable (LOW_QUALITY, DEGENERATE "
      "or FAILURE; counted by verdict in the summary and summary.json): its "
      "pose is the prediction.";
  mlndt::tools::HideFlagsFromHelp(mlndt::tools::LocalizerRefusedFlags());
  if (!mlndt::tools::StartTool(usage, true, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
