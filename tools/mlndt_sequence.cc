// mlndt_sequence: registers a scan sequence pair by pair (scan i + step onto
// scan i), chains the estimates into a trajectory and, with ground truth,
// reports per-pair errors and totals in the layout of the paper's Tables 2-4.
//
//   mlndt_sequence DIR_OR_BAG (or --scans=DIR [--times=FILE] | --bag=FILE)
//                  [--topic=NAME] [--output_dir=OUT] [--gt_poses=FILE]
//                  [--step=1] [--init=zero|gt_fraction:c|...]
//                  [--adaptive_start_layer] [any mlndt_align registration flag]
//
// Scans: the point-cloud files in DIR by name, or a bag's --topic
// (tools/cli/scan_input.h). Ground truth: KITTI lines, world_from_scan per
// scan; with --poses_are_camera --calib KITTI camera poses, converted with
// the Tr line (pose_flags.h), as for --init=poses:FILE.
//
// Initial guesses (reference_from_input):
//   zero               identity (the paper's Z_i = 0),
//   gt_fraction:c      the ground-truth motion with translation and rotation
//                      angle (axis-angle) scaled by c (Table 9's Z_i = c Z_gt),
//   constant_velocity  the previous pair's estimate (identity for the first),
//   poses:FILE         P_i^-1 P_{i+step} from a KITTI pose file (odometry).
//
// Each scan's map is built once, when it first becomes the reference
// (Section 4.3; time_map_ms counts it in that pair); --method=ndt builds its
// own single grid per pair.
//
// --adaptive_start_layer: the paper's proposal (end of Section 5.3;
// lab/runs/adaptive_start_layer.h, tools/cli/adaptive_start_layer_flags.h).
//
// Writes into --output_dir: pairs.csv, summary.json, trace.csv,
// trajectory_kitti.txt (chained estimates of scans 0, step, 2 step, ...; KITTI,
// first pose identity), trajectory_tum.txt (the same, stamped as its header
// line says), gt_trajectory_kitti.txt (from the ground truth), and with --plots
// the PNGs errors_translation, errors_rotation, trajectory_xy and
// score_vs_iteration (gnuplot; data and scripts in plot_data/). Pairs are
// counted by verdict (summary.json "terminations", the printed "verdicts:"
// line); a pair whose result is not usable (LOW_QUALITY, DEGENERATE,
// FAILURE) keeps its --init guess as its estimate, chained into
// trajectory_kitti.txt, and is flagged in pairs.csv and summary.json.
//
// Exit codes: 2 on input refused before any work; 1 when a pair's result
// is not usable, data cannot be read or gnuplot is missing for --plots (the
// other files are still written).

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "lab/report/gnuplot.h"
#include "lab/report/sequence_plots.h"
#include "lab/runs/scan_store.h"
#include "lab/runs/sequence_registration.h"
#include "tools/cli/output_files.h"
#include "tools/cli/output_set.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/progress_printer.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/scan_input.h"
#include "tools/cli/sequence_flags.h"
#include "tools/cli/sequence_inputs.h"
#include "tools/cli/sequence_output.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_string(gt_poses, "", "Optional KITTI poses, one line per scan (world_from_scan)");
DEFINE_string(init, "zero", "Initial guess: zero | gt_fraction:c | constant_velocity | poses:FILE");
DEFINE_int32(max_scans, 0, "Use only the first N scans (0 = all)");
DEFINE_string(output_dir, "", "Folder for pairs.csv, summary.json, trajectories and plots");
DEFINE_bool(plots, true, "Write PNG figures with gnuplot (exit 1 when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
DEFINE_int32(trace_plot_pairs, 3, "Pairs shown in score_vs_iteration.png");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_sequence";

// The run's options from the flags; false with *error for bad values.
bool SequenceOptionsFromFlags(SequenceOptions* options, std::string* error) {
  if ((FLAGS_scans.empty() && FLAGS_bag.empty()) || FLAGS_output_dir.empty()) {
    *error =
        "Usage: mlndt_sequence DIR_OR_BAG [--topic=NAME] "
        "[--output_dir=OUT] [--gt_poses=FILE] ...";
    return false;
  }
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  options->release_used_scans = true;
  if (!tools::SequenceFlags().Apply(options, error) ||
      !tools::MatcherOptionsFromFlags(&options->registration, error) ||
      !ParseInitSpec(FLAGS_init, &options->init, error) ||
      !tools::AdaptiveOptionsFromFlags(&options->adaptive, error)) {
    return false;
  }
  if (options->adaptive.enabled &&
      options->registration.method != Method::MLNDT) {
    *error = "--adaptive_start_layer needs --method=mlndt (NDT has one layer)";
    return false;
  }
  if (FLAGS_trace_plot_pairs < 0) {
    *error = "--trace_plot_pairs must be >= 0";
    return false;
  }
  if (!tools::CheckCameraPoseFlags(
          "--gt_poses or --init=poses:FILE",
          !FLAGS_gt_poses.empty() || options->init.mode == InitMode::POSES,
          error)) {
    return false;
  }
  return true;
}

// The files, the totals on stdout, the plots, and summary.json last
// (output_set.h): 0, or the exit code of a failed write or plot.
int WriteOutputs(const SequenceOptions& options,
                 const tools::ScanInput& input,
                 const ScanStore& store,
                 const std::vector<PairResult>& results,
                 const std::vector<Isometry3d>& truth,
                 bool gnuplot_ok) {
  std::string error;
  const tools::SequenceSource source = {
      FLAGS_scans, FLAGS_bag, input.topic(), tools::IntFlag("start_layer")};
  const tools::Json header =
      tools::SequenceSummaryHeader(options, source, store.size());
  if (!tools::WriteSequenceFiles(FLAGS_output_dir,
                                 options,
                                 input,
                                 store,
                                 results,
                                 !truth.empty(),
                                 &error)) {
    return tools::Fail(kTool, error);
  }
  PrintSequenceTotals(options, results, FLAGS_output_dir);
  std::string plot_error;
  std::vector<std::string> pngs;
  bool plotted = false;
  if (FLAGS_plots && !gnuplot_ok) {
    plot_error = PlotSkippedMessage(FLAGS_gnuplot, "plots");
  } else if (FLAGS_plots) {
    plotted = WriteSequencePlots(FLAGS_gnuplot,
                                 FLAGS_output_dir,
                                 results,
                                 options.step,
                                 FLAGS_trace_plot_pairs,
                                 &pngs,
                                 &plot_error);
    std::string list;  // "plots: a.png, b.png, ..." on stdout.
    for (const std::string& p : pngs) list += (list.empty() ? "" : ", ") + p;
    if (plotted) std::printf("plots: %s\n", list.c_str());
  }
  std::vector<std::string> files;
  for (const std::string& file :
       tools::SequenceOutputFiles(!truth.empty(), FLAGS_plots)) {
    const bool png = file.size() > 4 && file.substr(file.size() - 4) == ".png";
    if (file != "summary.json" && (!png || plotted)) files.push_back(file);
  }
  if (!tools::FinishOutputSet(FLAGS_output_dir,
                              files,
                              tools::SummaryJson(header, results),
                              &error)) {
    return tools::Fail(kTool, error);
  }
  return FLAGS_plots && !plotted ? tools::Fail(kTool, plot_error) : 0;
}

int Run() {
  SequenceOptions options;
  std::string error;
  if (!SequenceOptionsFromFlags(&options, &error))
    return tools::Refuse(kTool, error);
  if (options.registration.method == Method::MLNDT &&
      !tools::CheckStartLayerBeforeMap(options.registration.mlndt, &error)) {
    return tools::Refuse(kTool, error);
  }
  tools::ScanInput input;
  std::vector<Isometry3d> truth, odometry;
  if (!tools::ReadSequenceInputs(options,
                                 FLAGS_scans,
                                 FLAGS_gt_poses,
                                 FLAGS_max_scans,
                                 &input,
                                 &truth,
                                 &odometry,
                                 &error)) {
    return tools::Refuse(kTool, error);
  }
  if (!tools::PrepareOutputDir(
          "output_dir",
          FLAGS_output_dir,
          tools::SequenceOutputFiles(!truth.empty(), FLAGS_plots),
          &error) ||
      !tools::StartOutputSet(FLAGS_output_dir, &error)) {
    return tools::Refuse(kTool, error);
  }
  const bool gnuplot_ok =
      GnuplotReadyForPlots(kTool,
                           FLAGS_plots,
                           FLAGS_gnuplot,
                           "plots will be skipped (install gnuplot-nox, "
                           "e.g. with scripts/install_deps.sh, or pass "
                           "--plots=false)");

  ScanStore store = input.from_bag() ? ScanStore(input.names(), input.Loader())
                                     : ScanStore(input.paths());
  std::vector<PairResult> results;
  tools::ProgressPrinter progress(kTool);
  const bool ok = RunSequence(options,
                              &store,
                              truth.empty() ? nullptr : &truth,
                              odometry.empty() ? nullptr : &odometry,
                              &progress,
                              &results,
                              &error);
  progress.Finish();
  if (!ok) return tools::Fail(kTool, error);
  const int written =
      WriteOutputs(options, input, store, results, truth, gnuplot_ok);
  if (written != 0) return written;
  // A pair without a usable result (LOW_QUALITY, DEGENERATE, FAILURE) has
  // its --init guess in trajectory_kitti.txt, flagged in pairs.csv and
  // summary.json.
  const std::string unusable = tools::UnusablePairsMessage(options, results);
  return unusable.empty() ? 0 : tools::Fail(kTool, unusable);
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Registers a scan sequence pair by pair and evaluates it against "
          "ground truth.\n"
          "  mlndt_sequence DIR_OR_BAG [--topic=NAME] "
          "[--output_dir=OUT] [--gt_poses=FILE] "
          "[--step=1] [--init=zero]\n"
          "Exit 1 when any pair's result is not usable (LOW_QUALITY, "
          "DEGENERATE or FAILURE; counted by verdict in the summary and "
          "summary.json): trajectory_kitti.txt holds its --init guess instead.",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
