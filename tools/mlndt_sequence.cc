// mlndt_sequence: registers a scan sequence pair by pair (scan i + step onto
// scan i), chains the estimates into a trajectory and, with ground truth,
// reports per-pair errors and totals in the layout of the paper's Tables 2-4.
//
//   mlndt_sequence (--scans=DIR [--times=FILE] | --bag=FILE --topic=NAME)
//                  --output_dir=OUT [--gt_poses=poses.txt
//   [--poses_are_camera --calib=calib.txt]]
//                  [--step=1]
//                  [--init=zero|gt_fraction:c|constant_velocity|poses:FILE]
//                  [--adaptive_start_layer] [any mlndt_align registration flag]
//
// Scans are the point-cloud files in DIR (by extension), sorted by file
// name; pose and calibration files given on the command line are left out
// even when they sit in DIR. Or the sensor_msgs/PointCloud2 messages of
// --topic in the ROS 1 bag --bag, in bag order (tools/common/scan_input.h).
// Ground-truth poses are KITTI lines, one per scan, world_from_scan in the
// scans' own frame; with --poses_are_camera
// --calib they are KITTI camera poses and are converted with the Tr line
// (V = Tr^-1 P Tr; pose_flags.h). --calib applies to --init=poses:FILE too.
//
// Initial guesses (reference_from_input):
//   zero               identity (the paper's Z_i = 0),
//   gt_fraction:c      the ground-truth motion with translation and rotation
//                      angle (axis-angle) scaled by c (Table 9's Z_i = c Z_gt),
//   constant_velocity  the previous pair's estimate (identity for the first),
//   poses:FILE         P_i^-1 P_{i+step} from a KITTI pose file (odometry).
//
// Each scan's map is built once, when the scan first becomes the reference,
// and registration runs on the prebuilt map (Section 4.3); the map time is
// reported separately (time_map_ms) and counted in the pair that built it.
// --method=ndt builds its own single grid per pair (no prebuilt-grid API).
//
// --adaptive_start_layer: the paper's proposal (end of Section 5.3), defined
// precisely in lab/runs/adaptive_start_layer.h: start on the last layer;
// a pair fails when its estimate is more than 1 m or 15 deg from its --init
// guess (or the registration fails); while the running fail rate over the
// pairs so far exceeds 5 % start one layer coarser, above 20 % two coarser.
//
// Writes into --output_dir: pairs.csv, summary.json, trace.csv,
// trajectory.txt (chained estimates of scans 0, step, 2 step, ...; KITTI
// format, first pose identity), trajectory_tum.txt (the same, stamped with
// the bag's header stamps or --times, else the scan indices, as its header
// line says), gt_trajectory.txt (same scans, from the
// ground truth), and with --plots the PNGs errors_translation,
// errors_rotation, trajectory_xy and score_vs_iteration (gnuplot; data and
// scripts in plot_data/). Pairs are counted by verdict (summary.json
// "terminations", the printed "verdicts:" line); a pair whose result is not
// usable (LOW_QUALITY, DEGENERATE, FAILURE) keeps its --init guess as its
// estimate, chained into trajectory.txt, and is flagged in pairs.csv
// (usable 0, estimate_source guess) and summary.json (unusable_pair_list).
//
// Exit codes: 2 on bad flags or input refused before any work; 1 when any
// pair's result is not usable (every file is still written), data cannot be
// read, or plots were requested but gnuplot is missing (the other files are
// still written); 0 when every pair is usable.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "lab/eval/dataset.h"
#include "lab/eval/pose_convention.h"
#include "lab/eval/trajectory_io.h"
#include "lab/runs/scan_store.h"
#include "lab/runs/sequence_registration.h"
#include "lab/runs/sequence_totals.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"
#include "tools/common/gnuplot.h"
#include "tools/common/json_output.h"
#include "tools/common/list_flags.h"
#include "tools/common/output_files.h"
#include "tools/common/pose_flags.h"
#include "tools/common/progress.h"
#include "tools/common/registration_flags.h"
#include "tools/common/scan_input.h"
#include "tools/common/sequence_output.h"
#include "tools/common/sequence_plots.h"
#include "tools/common/start_layer_check.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"
#include "tools/common/verdict_counts.h"

// clang-format off
DEFINE_string(scans, "", "Folder of scans (every point-cloud file in it, sorted by file name)");
DEFINE_string(gt_poses, "", "Optional KITTI poses, one line per scan (world_from_scan)");
DEFINE_int32(step, 1, "Register scan i + step onto scan i (>= 1)");
DEFINE_string(init, "zero", "Initial guess: zero | gt_fraction:c | constant_velocity | poses:FILE");
DEFINE_int32(max_scans, 0, "Use only the first N scans (0 = all)");
DEFINE_string(output_dir, "", "Folder for pairs.csv, summary.json, trajectories and plots");
DEFINE_bool(plots, true, "Write PNG figures with gnuplot (exit 1 when gnuplot is missing)");
DEFINE_string(gnuplot, "gnuplot", "The gnuplot program");
DEFINE_int32(trace_plot_pairs, 3, "Pairs shown in score_vs_iteration.png");
DEFINE_bool(adaptive_start_layer, false,
            "Paper's adaptive start layer: last layer, coarser as the fail rate grows");
DEFINE_double(adaptive_max_translation, 1.0,
              "Adaptive: a deviation from the --init guess above this [m] is a failure");
DEFINE_double(adaptive_max_rotation, 15.0,
              "Adaptive: a deviation from the --init guess above this [deg] is a failure");
DEFINE_string(adaptive_fail_rates, "0.05,0.2",
              "Adaptive: ascending running fail rates; above the k-th start k layers coarser");
// clang-format on

namespace mlndt {
namespace {

int Fail(const std::string& message) {
  std::cerr << "mlndt_sequence: " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << "mlndt_sequence: " << message << std::endl;
  return tools::kExitUsage;
}

bool AdaptiveOptionsFromFlags(AdaptiveStartLayerOptions* adaptive,
                              std::string* error) {
  adaptive->enabled = FLAGS_adaptive_start_layer;
  adaptive->max_translation_m = FLAGS_adaptive_max_translation;
  adaptive->max_rotation_deg = FLAGS_adaptive_max_rotation;
  if (!(adaptive->max_translation_m > 0) || !(adaptive->max_rotation_deg > 0)) {
    *error =
        "--adaptive_max_translation and --adaptive_max_rotation must be > 0";
    return false;
  }
  std::vector<double> rates;
  if (!tools::ParseNumberList(FLAGS_adaptive_fail_rates, &rates) ||
      !std::is_sorted(rates.begin(), rates.end()) ||
      std::any_of(rates.begin(), rates.end(), [](double r) {
        return r < 0 || r > 1;
      })) {
    *error = "--adaptive_fail_rates=" + FLAGS_adaptive_fail_rates +
             ": expected ascending numbers in [0, 1], e.g. 0.05,0.2";
    return false;
  }
  adaptive->fail_rate_thresholds = rates;
  return true;
}

// The run's options from the flags; false with *error for bad values.
bool SequenceOptionsFromFlags(SequenceOptions* options, std::string* error) {
  if ((FLAGS_scans.empty() && FLAGS_bag.empty()) || FLAGS_output_dir.empty()) {
    *error =
        "Usage: mlndt_sequence (--scans=DIR | --bag=FILE --topic=NAME) "
        "--output_dir=OUT [--gt_poses=FILE] ...";
    return false;
  }
  if (FLAGS_step < 1) {
    *error = "--step must be >= 1";
    return false;
  }
  if (FLAGS_max_scans < 0) {
    *error = "--max_scans must be >= 0";
    return false;
  }
  options->step = static_cast<size_t>(FLAGS_step);
  options->release_used_scans = true;
  if (!tools::MatcherOptionsFromFlags(&options->registration, error) ||
      !ParseInitSpec(FLAGS_init, &options->init, error) ||
      !AdaptiveOptionsFromFlags(&options->adaptive, error)) {
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

// The scans (at most --max_scans) and, when given, the ground truth and
// the odometry of --init=poses:FILE, one pose per scan.
bool ReadScansAndPoses(const SequenceOptions& options,
                       tools::ScanInput* input,
                       std::vector<Isometry3d>* truth,
                       std::vector<Isometry3d>* odometry,
                       std::string* error) {
  const auto list_folder = [&](std::vector<std::string>* paths,
                               std::string* list_error) {
    return ListScanFiles(
        FLAGS_scans,
        {FLAGS_gt_poses, FLAGS_calib, options.init.poses_path, FLAGS_times},
        paths,
        list_error);
  };
  if (!tools::ScanInputFromFlags(!FLAGS_scans.empty(),
                                 list_folder,
                                 static_cast<size_t>(FLAGS_max_scans),
                                 input,
                                 error)) {
    return false;
  }
  const std::vector<std::string>* paths = &input->names();
  const std::string scans = std::to_string(paths->size()) + " scans";
  if (paths->size() <= options.step) {
    *error = (FLAGS_bag.empty() ? FLAGS_scans : FLAGS_bag) + ": " + scans +
             ", too few for --step=" + std::to_string(options.step);
    return false;
  }
  if (!FLAGS_gt_poses.empty() &&
      !ReadSequencePoses(FLAGS_gt_poses, FLAGS_calib, truth, error)) {
    return false;
  }
  std::string evidence;
  if (!FLAGS_poses_are_camera && LooksLikeCameraPoses(*truth, &evidence)) {
    std::cerr << "mlndt_sequence: WARNING: --gt_poses=" << FLAGS_gt_poses
              << " looks like KITTI camera (cam0) poses read as the scans' "
                 "own: "
              << evidence
              << ". If it is KITTI's poses/XX.txt, add --poses_are_camera "
                 "--calib=calib.txt; else every error below is measured "
                 "against the wrong frame.\n";
  }
  if (!truth->empty() && truth->size() < paths->size()) {
    *error = FLAGS_gt_poses + " has " + std::to_string(truth->size()) +
             " poses for " + scans;
    return false;
  }
  if (options.init.mode == InitMode::GT_FRACTION && truth->empty()) {
    *error = "--init=gt_fraction:c needs --gt_poses";
    return false;
  }
  if (options.init.mode != InitMode::POSES) return true;
  if (!ReadSequencePoses(
          options.init.poses_path, FLAGS_calib, odometry, error)) {
    return false;
  }
  if (odometry->size() < paths->size()) {
    *error = options.init.poses_path + " has " +
             std::to_string(odometry->size()) + " poses for " + scans;
    return false;
  }
  return true;
}

// One progress line per pair.
std::string PairDetail(const PairResult& r) {
  char detail[160];
  int used = std::snprintf(detail,
                           sizeof(detail),
                           "pair %zu->%zu %s, %d it, %.0f ms",
                           r.reference,
                           r.input,
                           TerminationTypeToString(r.termination),
                           r.iterations,
                           r.times.total_ms);
  if (r.has_truth && used > 0 && used < static_cast<int>(sizeof(detail))) {
    std::snprintf(detail + used,
                  sizeof(detail) - used,
                  ", error %.1f cm %.2f deg",
                  r.error.translation_m * 100.0,
                  r.error.rotation_rad * kRadToDeg);
  }
  return detail;
}

// The schema header and the run's settings, first in summary.json.
tools::Json SummaryHeader(const SequenceOptions& options, size_t num_scans) {
  const MatcherOptions& registration = options.registration;
  tools::Json header = tools::ToolJson("mlndt_sequence");
  header["scans_dir"] = FLAGS_scans;
  if (!FLAGS_bag.empty()) {
    header["bag"] = FLAGS_bag;
    header["topic"] = FLAGS_topic;
  }
  header["scans"] = num_scans;
  header["step"] = options.step;
  header["init"] = InitSpecToString(options.init);
  header["method"] = MethodToString(registration.method);
  header["backend"] = BackendTypeToString(registration.mlndt.backend.type);
  header["sampling"] = SamplingMethodToString(
      registration.method == Method::NDT ? registration.ndt.sampling.method
                                         : registration.mlndt.sampling.method);
  header["adaptive_start_layer"] = options.adaptive.enabled;
  if (options.adaptive.enabled) {
    tools::Json thresholds = tools::Json::array();
    for (const double v : options.adaptive.fail_rate_thresholds) {
      thresholds.push_back(tools::Number(v));
    }
    header["adaptive"] = {
        {"max_translation_m",
         tools::Number(options.adaptive.max_translation_m)},
        {"max_rotation_deg", tools::Number(options.adaptive.max_rotation_deg)},
        {"fail_rate_thresholds", thresholds}};
  } else {
    header["start_layer_flag"] = tools::IntFlag("start_layer");
  }
  return header;
}

// pairs.csv, trace.csv, summary.json and the trajectories.
// The chained trajectory in TUM format, stamped with the scans' times.
bool WriteTumTrajectory(const std::string& path,
                        const std::vector<Isometry3d>& poses,
                        size_t step,
                        const tools::ScanInput& input,
                        std::string* error) {
  Trajectory trajectory;
  for (size_t k = 0; k < poses.size(); ++k) {
    trajectory.Add(input.StampOf(k * step), poses[k]);
  }
  return WriteTrajectory(
      path, TrajectoryFormat::TUM, trajectory, input.TumComment(), error);
}

bool WriteFiles(const SequenceOptions& options,
                const tools::ScanInput& input,
                const ScanStore& store,
                const std::vector<PairResult>& results,
                bool has_truth,
                std::string* error) {
  const std::string out = FLAGS_output_dir + "/";
  if (!tools::WritePairsCsv(out + "pairs.csv", store, results, error) ||
      !tools::WriteTraceCsv(out + "trace.csv", results, error)) {
    return false;
  }
  if (!tools::WriteJsonFile(
          out + "summary.json",
          tools::SummaryJson(SummaryHeader(options, store.size()), results),
          error)) {
    return false;
  }
  const std::vector<Isometry3d> chained =
      ChainTrajectory(results, options.step, false);
  if (!WriteKittiPoses(out + "trajectory.txt", chained, error) ||
      !WriteTumTrajectory(
          out + "trajectory_tum.txt", chained, options.step, input, error)) {
    return false;
  }
  return !has_truth ||
         WriteKittiPoses(out + "gt_trajectory.txt",
                         ChainTrajectory(results, options.step, true),
                         error);
}

int WritePlots(const SequenceOptions& options,
               const std::vector<PairResult>& results,
               bool gnuplot_ok) {
  if (!gnuplot_ok) {
    return Fail("plots skipped: gnuplot ('" + FLAGS_gnuplot +
                "') not found; the other outputs are written. Install "
                "gnuplot-nox or pass "
                "--plots=false");
  }
  std::vector<std::string> pngs;
  std::string error;
  if (!tools::WriteSequencePlots(FLAGS_gnuplot,
                                 FLAGS_output_dir,
                                 results,
                                 options.step,
                                 FLAGS_trace_plot_pairs,
                                 &pngs,
                                 &error)) {
    return Fail(error);
  }
  std::printf("plots: ");
  for (size_t k = 0; k < pngs.size(); ++k)
    std::printf("%s%s", k ? ", " : "", pngs[k].c_str());
  std::printf("\n");
  return 0;
}

// 1 when any pair's result is not usable (LOW_QUALITY, DEGENERATE, FAILURE):
// its --init guess stands in for it in trajectory.txt, flagged in pairs.csv
// and summary.json.
int ExitForVerdicts(const SequenceOptions& options,
                    const std::vector<PairResult>& results) {
  tools::VerdictCounts verdicts;
  std::string pairs;
  for (const PairResult& r : results) {
    verdicts.Add(r.termination);
    if (!IsUsableTermination(r.termination) && pairs.size() < 200) {
      pairs += (pairs.empty() ? "" : ", ") + std::to_string(r.reference) +
               "->" + std::to_string(r.input) + " " +
               TerminationTypeToString(r.termination);
    }
  }
  if (verdicts.unusable() == 0) return 0;
  return Fail(std::to_string(verdicts.unusable()) + " of " +
              std::to_string(verdicts.total()) +
              " pairs have no usable result (" + pairs +
              "): trajectory.txt chains their --init=" +
              InitSpecToString(options.init) +
              " guess instead (estimate_source 'guess' in pairs.csv)");
}

int Run() {
  SequenceOptions options;
  std::string error;
  if (!SequenceOptionsFromFlags(&options, &error)) return Refuse(error);
  if (options.registration.method == Method::MLNDT &&
      !tools::CheckStartLayerBeforeMap(options.registration.mlndt, &error)) {
    return Refuse(error);
  }
  tools::ScanInput input;
  std::vector<Isometry3d> truth, odometry;
  if (!ReadScansAndPoses(options, &input, &truth, &odometry, &error)) {
    return Refuse(error);
  }
  if (!tools::PrepareOutputDir("output_dir",
                               FLAGS_output_dir,
                               {"pairs.csv", "summary.json"},
                               &error)) {
    return Refuse(error);
  }
  const bool gnuplot_ok =
      !FLAGS_plots || tools::GnuplotAvailable(FLAGS_gnuplot);
  if (!gnuplot_ok) {
    std::cerr << "mlndt_sequence: gnuplot ('" << FLAGS_gnuplot
              << "') not found: plots will be skipped (install gnuplot-nox, "
                 "e.g. with "
                 "scripts/install_deps.sh, or pass --plots=false)\n";
  }

  ScanStore store = input.from_bag() ? ScanStore(input.names(), input.Loader())
                                     : ScanStore(input.paths());
  tools::Progress progress("mlndt_sequence", input.size() - options.step);
  std::vector<PairResult> results;
  const auto on_pair = [&](const PairResult& r, size_t done, size_t) {
    progress.Update(done, PairDetail(r));
  };
  const bool ok = RunSequence(options,
                              &store,
                              truth.empty() ? nullptr : &truth,
                              odometry.empty() ? nullptr : &odometry,
                              on_pair,
                              &results,
                              &error);
  progress.Finish();
  if (!ok) return Fail(error);
  if (!WriteFiles(options, input, store, results, !truth.empty(), &error)) {
    return Fail(error);
  }
  tools::PrintSequenceTotals(options, results, FLAGS_output_dir);
  const int plots = FLAGS_plots ? WritePlots(options, results, gnuplot_ok) : 0;
  return plots != 0 ? plots : ExitForVerdicts(options, results);
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Registers a scan sequence pair by pair and evaluates it against "
          "ground truth.\n"
          "  mlndt_sequence (--scans=DIR | --bag=FILE --topic=NAME) "
          "--output_dir=OUT [--gt_poses=FILE] "
          "[--step=1] [--init=zero]\n"
          "Exit 1 when any pair's result is not usable (LOW_QUALITY, "
          "DEGENERATE or FAILURE; counted by verdict in the summary and "
          "summary.json): trajectory.txt holds its --init guess instead.",
          true,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
