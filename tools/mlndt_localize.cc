// mlndt_localize: registers every scan of a folder (or a list file) onto a
// saved layered map (mlndt_map) with ML-NDT, one scan at a time.
//
//   mlndt_localize --map=map.mlndt DIR_OR_BAG (or --scans=DIR
//                  [--times=FILE] | --bag=FILE [--topic=NAME])
//                  [--output_dir=OUT]
//                  [--initial_guess=tx,ty,tz,a,b,g | --initial_matrix=...
//                   | --initial_poses=FILE [--poses_are_camera
//                   --calib=calib.txt]]
//                  | --guesses=FILE]
//                  [--motion_model=constant_velocity|constant_pose]
//                  [--plots=false] [any registration flag of mlndt_align]
//
// The first scan starts from --initial_guess (m, deg, R = Rx Ry Rz),
// --initial_matrix (row-major 3x4) or the first pose of --initial_poses,
// else the identity (map_from_scan); each next one from the prediction
// (Localizer, mlndt/pipeline/localizer.h). With --guesses=FILE (TUM) every
// scan starts from its own guess, matched by stamp (localize_guesses.h).
//
// Writes into --output_dir: trajectory_kitti.txt and trajectory_tum.txt
// (map_from_scan; TUM stamps as the file's first line says), scans.csv and
// scans.json (LocalizationResultTable), summary.json, and with --plots
// (default) the top view trajectory_xy.png of the map's finest cells
// (subsampled to --plot_max_cells) and the trajectory (gnuplot; data and
// script in plot_data/). The summary counts the scans by verdict; a scan
// whose verdict is not usable (IsUsableTermination) keeps its prediction.
//
// Exit codes: 2 on input refused before any work; 1 when a scan's result
// is not usable, a scan cannot be read, an output cannot be written or
// gnuplot is missing for --plots (the other files are still written).

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "lab/report/gnuplot.h"
#include "mlndt/common/timer.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/pipeline/localizer.h"
#include "tools/cli/localize_guesses.h"
#include "tools/cli/localize_output.h"
#include "tools/cli/localizer_flags.h"
#include "tools/cli/map_flags.h"
#include "tools/cli/map_inputs.h"
#include "tools/cli/output_files.h"
#include "tools/cli/output_set.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/scan_input.h"
#include "tools/cli/tool_main.h"

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
DEFINE_string(guesses, "", "TUM file: each scan's guess, matched by stamp (or index)");
DEFINE_double(guesses_max_time_difference_s, 0.01, "A scan's guess is within this of its stamp");
DEFINE_string(output_dir, "", "Folder for the trajectories, scans.csv, summary.json and the plot");
DEFINE_bool(plots, true, "Write trajectory_xy.png with gnuplot (exit 1 when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
DEFINE_int32(plot_max_cells, 20000, "Finest-layer cell means drawn in the top view (subsampled), "
             ">= 0");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_localize";

// Every flag is checked and the guesses read here, before the map or any
// scan is read.
bool CheckFlags(LocalizerOptions* options,
                tools::ScanInput* input,
                Isometry3d* first_guess,
                std::vector<Isometry3d>* guesses,
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
  if (!tools::CheckMapFile(FLAGS_map, error)) return false;
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  if (FLAGS_plot_max_cells < 0) {
    *error = "--plot_max_cells must be >= 0";
    return false;
  }
  if (!tools::CheckInitialPoseFlags(FLAGS_initial_guess,
                                    FLAGS_initial_matrix,
                                    FLAGS_initial_poses,
                                    error) ||
      !tools::CheckGuessesFlag(
          FLAGS_guesses,
          FLAGS_initial_guess + FLAGS_initial_matrix + FLAGS_initial_poses,
          FLAGS_guesses_max_time_difference_s,
          error)) {
    return false;
  }
  // --motion_model (LocalizerOwnOptionsTable).
  if (!tools::LocalizerFlags().Apply(options, error)) return false;
  if (!tools::RefuseMapFlags(kTool, error) ||
      !tools::RegistrationOptionsFromFlags(
          LocalizerRegistrationOptions(), &options->registration, error)) {
    return false;
  }
  if (!options->IsValid(error)) return false;
  return tools::ScanInputFromScanListFlags(
             FLAGS_scans,
             FLAGS_scan_list,
             {FLAGS_map, FLAGS_initial_poses, FLAGS_calib, FLAGS_times},
             static_cast<size_t>(FLAGS_max_scans),
             input,
             error) &&
         input->ReadBagStamps(error) &&
         tools::InitialGuessesFromFlags({FLAGS_initial_guess,
                                         FLAGS_initial_matrix,
                                         FLAGS_initial_poses,
                                         FLAGS_initial_poses_format,
                                         FLAGS_calib},
                                        FLAGS_guesses,
                                        FLAGS_guesses_max_time_difference_s,
                                        *input,
                                        first_guess,
                                        guesses,
                                        error);
}

// trajectory_xy.png; exit code 1 when gnuplot is missing or fails.
int Plot(bool gnuplot_ok,
         const LayeredGrid& map,
         const std::vector<LocalizationResult>& results) {
  return tools::WriteLocalizationPlotOrFail(kTool,
                                            gnuplot_ok,
                                            FLAGS_output_dir,
                                            map,
                                            results,
                                            FLAGS_plot_max_cells,
                                            FLAGS_gnuplot);
}

int Run() {
  const double start = NowSeconds();
  LocalizerOptions options;
  tools::ScanInput input;
  std::string error;
  Isometry3d first_guess;
  std::vector<Isometry3d> guesses;
  if (!CheckFlags(&options, &input, &first_guess, &guesses, &error))
    return tools::Refuse(kTool, error);
  const std::vector<std::string>& paths = input.names();
  LayeredGrid map;
  if (!tools::LoadLocalizationMap(FLAGS_map, options, &map, &error)) {
    return tools::Refuse(kTool, error);
  }
  const double map_load_s = NowSeconds() - start;
  if (!tools::PrepareOutputDir("output_dir",
                               FLAGS_output_dir,
                               tools::LocalizationOutputFiles(),
                               &error) ||
      !tools::StartOutputSet(FLAGS_output_dir, &error)) {
    return tools::Refuse(kTool, error);
  }
  const bool gnuplot_ok = GnuplotReadyForPlots(
      kTool,
      FLAGS_plots,
      FLAGS_gnuplot,
      "the plot will be skipped (install gnuplot-nox, or pass --plots=false)");

  tools::PrintMapLine(FLAGS_map, map);

  // Each scan from the prediction, or with --guesses from its own guess.
  tools::ProgressPrinter progress(kTool, paths);
  std::vector<LocalizationResult> results;
  const ScanLoader load = input.Loader();
  const bool ok =
      guesses.empty()
          ? LocalizeScans(options,
                          map,
                          first_guess,
                          paths.size(),
                          load,
                          &progress,
                          &results,
                          &error)
          : LocalizeScansFromGuesses(
                options, map, guesses, load, &progress, &results, &error);
  progress.Finish();
  if (!ok) return tools::Fail(kTool, error);

  if (!tools::WriteLocalizationFiles(
          FLAGS_output_dir, input, results, &error)) {
    return tools::Fail(kTool, error);
  }
  const VerdictCounts verdicts = tools::PrintLocalizationTable(paths, results);
  std::printf("output: %s\n", FLAGS_output_dir.c_str());
  const int plot = FLAGS_plots ? Plot(gnuplot_ok, map, results) : 0;
  if (!tools::FinishLocalizationOutputs(
          FLAGS_output_dir,
          FLAGS_plots && plot == 0,
          tools::LocalizationSummaryJson(options,
                                         FLAGS_map,
                                         map,
                                         first_guess,
                                         results,
                                         map_load_s,
                                         NowSeconds() - start),
          &error)) {
    return tools::Fail(kTool, error);
  }
  if (plot != 0) return plot;
  if (verdicts.unusable() > 0) {
    return tools::Fail(kTool, tools::UnusableScansMessage(verdicts));
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  mlndt::tools::ShowRegistrationDefaults(mlndt::LocalizerRegistrationOptions());
  const char* usage =
      "Registers every scan of a folder onto a saved map (mlndt_map).\n"
      "  mlndt_localize --map=map.mlndt DIR_OR_BAG [--output_dir=OUT] "
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
