#include "tools/cli/localize_output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <utility>

#include "lab/eval/statistics.h"
#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/grid/map_memory.h"
#include "tools/cli/output_set.h"
#include "tools/cli/scan_files.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/tool_utils.h"
#include "tools/cli/verdict_counts_json.h"

namespace mlndt {
namespace tools {
namespace {

// trajectory_xy.png: the finest layer's cell means (every k-th, at most
// plot_max_cells) and the trajectory, seen from above.
bool WriteLocalizationPlot(const std::string& dir,
                           const LayeredGrid& map,
                           const std::vector<LocalizationResult>& results,
                           int plot_max_cells,
                           const std::string& gnuplot,
                           std::string* error) {
  std::string data_dir;
  if (!MakePlotDataDir(dir, &data_dir, error)) return false;
  const std::vector<NdtCell>& cells = map.layer(map.num_layers()).cells();
  const size_t max_cells = static_cast<size_t>(plot_max_cells);
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
                 << (r.registration.termination_type ==
                     TerminationType::CONVERGENCE)
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
  script << GnuplotPngHeader(1000, 800) << GnuplotSetOutput(png)
         << "set title 'Map (finest cell means) and trajectory, top view'\n"
         << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\n"
         << "plot " << GnuplotQuote(data_dir + "/map_cells.dat")
         << " using 1:2 with points pt 7 ps 0.3 lc rgb '#a0a0a0' title 'map "
            "cells', "
         << GnuplotQuote(data_dir + "/trajectory.dat")
         << " using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#c00000' "
            "title 'trajectory'\n";
  return RunGnuplot(gnuplot, data_dir + "/plot.gp", script.str(), {png}, error);
}

}  // namespace

Json LocalizationSummaryJson(const LocalizerOptions& options,
                             const std::string& map_path,
                             const LayeredGrid& map,
                             const Isometry3d& first_guess,
                             const std::vector<LocalizationResult>& results,
                             double map_load_s,
                             double total_s) {
  VerdictCounts verdicts;
  std::vector<double> registration_ms, inliers, own;
  for (const LocalizationResult& r : results) {
    verdicts.Add(r.registration.termination_type);
    registration_ms.push_back(r.registration.total_time_s * 1e3);
    inliers.push_back(r.registration.quality.inlier_fraction);
    own.push_back(r.registration.quality.own_cell_fraction);
  }
  size_t cells = 0;
  for (int i = 1; i <= map.num_layers(); ++i) {
    cells += map.layer(i).cells().size();
  }
  Json json = ToolJson("mlndt_localize");
  json["map"] = map_path;
  json["map_info"] = {
      {"layers", map.num_layers()},
      {"cells", cells},
      {"bytes", map.MemoryBytes()},
      {"finest_cell_size_m", Number(map.layer(map.num_layers()).cell_size())}};
  json["scans"] = results.size();
  json["motion_model"] = MotionModelToString(options.motion_model);
  json["backend"] = BackendTypeToString(options.registration.backend.type);
  json["first_guess"] = PoseJson(first_guess);
  json["terminations"] = VerdictCountsJson(verdicts);
  json["usable"] = verdicts.usable();
  json["unusable"] = verdicts.unusable();
  json["unusable_pose"] =
      "the prediction (dead reckoning): LOW_QUALITY, DEGENERATE and FAILURE "
      "scans are not to be used";
  json["inlier_fraction"] = StatsJson(ComputeStats(inliers));
  json["own_cell_fraction"] = StatsJson(ComputeStats(own));
  json["time_ms"] = {{"total", Number(total_s * 1e3)},
                     {"map_load", Number(map_load_s * 1e3)}};
  json["time_ms_stats"] = {
      {"registration", StatsJson(ComputeStats(registration_ms))}};
  json["peak_resident_bytes"] = PeakResidentBytes();
  return json;
}

bool WriteLocalizationFiles(const std::string& dir,
                            const ScanInput& input,
                            const std::vector<LocalizationResult>& results,
                            std::string* error) {
  return WriteScanFilesOf(
      dir,
      "mlndt_localize",
      input,
      LocalizationResultTable(),
      results,
      [&input](const LocalizationResult& r) {
        return ScanPose{r.index, input.StampOf(r.index), r.map_from_scan};
      },
      error);
}

void PrintMapLine(const std::string& map_path, const LayeredGrid& map) {
  std::printf("map: %s, %d layers, finest cell %.3f m, %s\n",
              map_path.c_str(),
              map.num_layers(),
              map.layer(map.num_layers()).cell_size(),
              FormatBytes(static_cast<double>(map.MemoryBytes())).c_str());
}

std::string UnusableScansMessage(const VerdictCounts& verdicts) {
  return std::to_string(verdicts.unusable()) + " of " +
         std::to_string(verdicts.total()) + " scans have no usable pose (" +
         verdicts.Line() +
         "): their poses in the trajectories are the predictions; "
         "see the registration.termination_type column of scans.csv";
}

VerdictCounts PrintLocalizationTable(
    const std::vector<std::string>& paths,
    const std::vector<LocalizationResult>& results) {
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
  VerdictCounts verdicts;
  for (const LocalizationResult& r : results) {
    const Vector6d xi = IsometryToPoseVector(r.map_from_scan);
    std::printf(
        "%-5zu %-24s %-15s %5d %8.3f %8.3f %10.3f %10.3f %10.3f %9.1f "
        "%9.1f\n",
        r.index,
        std::filesystem::path(paths[r.index]).filename().c_str(),
        TerminationTypeToString(r.registration.termination_type),
        r.registration.num_iterations,
        r.registration.quality.own_cell_fraction,
        r.registration.quality.inlier_fraction,
        xi(0),
        xi(1),
        xi(5) * kRadToDeg,
        r.load_time_s * 1e3,
        r.registration.total_time_s * 1e3);
    registration_ms.push_back(r.registration.total_time_s * 1e3);
    verdicts.Add(r.registration.termination_type);
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
      FormatBytes(PeakResidentBytes()).c_str());
  return verdicts;
}

// What WriteLocalizationFiles writes, in the order summary.json names them.
const std::vector<std::string>& WrittenFiles() {
  static const std::vector<std::string> files = {
      "trajectory_kitti.txt", "trajectory_tum.txt", "scans.csv", "scans.json"};
  return files;
}

const std::vector<std::string>& LocalizationOutputFiles() {
  static const std::vector<std::string> files = [] {
    std::vector<std::string> all = WrittenFiles();
    all.push_back("summary.json");
    return all;
  }();
  return files;
}

bool FinishLocalizationOutputs(const std::string& dir,
                               bool plotted,
                               Json summary,
                               std::string* error) {
  std::vector<std::string> files = WrittenFiles();
  if (plotted) files.push_back("trajectory_xy.png");
  return FinishOutputSet(dir, files, std::move(summary), error);
}

bool LoadLocalizationMap(const std::string& path,
                         const LocalizerOptions& options,
                         LayeredGrid* map,
                         std::string* error) {
  return LoadLayeredGrid(path, map, error) &&
         CheckStartLayerForMap(
             options.registration.schedule, map->num_layers(), error);
}

int WriteLocalizationPlotOrFail(const char* tool,
                                bool gnuplot_ok,
                                const std::string& dir,
                                const LayeredGrid& map,
                                const std::vector<LocalizationResult>& results,
                                int plot_max_cells,
                                const std::string& gnuplot) {
  if (!gnuplot_ok) return Fail(tool, PlotSkippedMessage(gnuplot));
  std::string error;
  if (!WriteLocalizationPlot(
          dir, map, results, plot_max_cells, gnuplot, &error)) {
    return Fail(tool, error);
  }
  std::printf("plot: trajectory_xy.png\n");
  return 0;
}

}  // namespace tools
}  // namespace mlndt
