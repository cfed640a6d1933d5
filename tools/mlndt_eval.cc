// mlndt_eval: evaluates trajectories against a reference trajectory, with
// mlndt/eval: the absolute trajectory error (ATE) after an alignment, the
// relative pose error (RPE) over --delta frames, and the KITTI odometry
// devkit's segment errors (translation % and rotation deg/m over 100-800 m
// segments, reported for the lengths the trajectory is long enough for).
//
//   mlndt_eval --reference=gt.txt --estimate=a.txt[,b.tum,...]
//              [--alignment=se3|sim3|first_pose|none] [--delta=1]
//              [--output_json=eval.json]
//   mlndt_eval chain reference_pairs.json poses.txt
//
// Files are KITTI (12 numbers a line, the line index is the frame) or TUM
// ("t tx ty tz qx qy qz qw"); the format is detected (extension .kitti /
// .tum, else the first line) or given (--format for the estimates,
// --reference_format). Poses are paired by index (KITTI, the devkit's
// convention) or, when both have time stamps, by timestamp within
// --max_time_difference (--association; evo's nearest-stamp matching, so
// trajectories of different rates and offsets pair up by time). TUM files
// have stamps unless their header says they are scan indices (as the mlndt
// tools write when no times were known); a KITTI reference gets them from
// --reference_times (one stamp per pose, e.g. times.txt). --reference_calib
// converts a KITTI camera (cam0) reference into the Velodyne frame with the
// Tr line.
// By index (--association=auto without stamps) the two files must hold
// equally many poses; --association=index pairs the common prefix
// explicitly (the JSON's "poses" and "pairs" say how many).
//
// `chain PAIRS OUT` writes the KITTI pose file of the chained pairs of a
// reference_pairs.json (eval/reference_pairs.h): from the smallest
// reference index, each next scan is the nearest input of a pair from the
// current one ("i_(i+1)", or "0_2", "2_4", ... when the scan numbering has
// gaps); pose 0 is the identity and pose k+1 = pose k * reference_from_input
// of that pair, for as long as a next pair exists. One line per chained
// scan; the printed line lists the scans when they are not consecutive.
//
// Exit codes: 2 on a bad flag or an input refused before any work (an
// unreadable file, trajectories of different lengths paired by index); 1
// when an evaluation fails or an output cannot be written.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <iostream>
#include <map>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/reference_pairs.h"
#include "lab/eval/scan_times.h"
#include "lab/eval/trajectory_association.h"
#include "lab/eval/trajectory_io.h"
#include "lab/eval/trajectory_metrics.h"
#include "mlndt/cloud/pose_io.h"
#include "tools/common/flag_utils.h"
#include "tools/common/json_output.h"
#include "tools/common/list_flags.h"
#include "tools/common/map_inputs.h"
#include "tools/common/output_files.h"
#include "tools/common/tool_main.h"
#include "tools/common/tool_utils.h"

// clang-format off
DEFINE_string(reference, "", "The reference trajectory (KITTI or TUM)");
DEFINE_string(estimate, "", "Comma-separated trajectory files to evaluate (KITTI or TUM)");
DEFINE_string(format, "auto", "Format of the --estimate files: auto | kitti | tum");
DEFINE_string(reference_format, "auto", "Format of --reference: auto | kitti | tum");
DEFINE_string(reference_times, "", "Time stamps of a KITTI --reference: a file of one stamp [s] "
              "per pose (times.txt); then TUM estimates are associated by time");
DEFINE_string(reference_calib, "", "KITTI calib.txt: --reference holds camera (cam0) poses, "
              "converted into the Velodyne frame with its Tr line");
DEFINE_string(alignment, "se3", "ATE alignment: se3 | sim3 | first_pose | none");
DEFINE_int32(delta, 1, "RPE: frames (associated poses) between the two poses of a motion, >= 1");
DEFINE_string(association, "auto", "auto (timestamp when both files are TUM, else index) | "
              "index | timestamp");
DEFINE_double(max_time_difference, 0.02, "Timestamp association: largest |dt| [s], > 0");
DEFINE_string(segment_lengths, "100,200,300,400,500,600,700,800",
              "KITTI segment lengths [m], comma-separated, each > 0");
DEFINE_int32(segment_step, 10, "KITTI segments: a first frame every this many frames, >= 1");
DEFINE_string(output_json, "", "Also write the results as JSON to this file");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_eval";

int Fail(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitFailed;
}

// A flag, argument or input refused before any work (tool_main.h).
int Refuse(const std::string& message) {
  std::cerr << kTool << ": " << message << std::endl;
  return tools::kExitUsage;
}

const std::vector<std::string> kEvalFlags = {"reference",
                                             "estimate",
                                             "format",
                                             "reference_format",
                                             "reference_calib",
                                             "alignment",
                                             "delta",
                                             "association",
                                             "max_time_difference",
                                             "segment_lengths",
                                             "segment_step",
                                             "output_json"};

// ---- chain --------------------------------------------------------------

// The scans of the chain: from the smallest reference index, each next scan
// is the nearest input index of a pair from the current one ("i_(i+1)"
// when it exists; "0_2", "2_4", ... when the numbering has gaps).
std::vector<int64_t> ChainedScans(
    const std::map<std::string, ReferencePair>& pairs) {
  std::map<int64_t, int64_t> next;  // reference -> nearest input.
  for (const auto& [key, pair] : pairs) {
    if (pair.input_index <= pair.reference_index) continue;
    auto [it, added] = next.emplace(pair.reference_index, pair.input_index);
    if (!added) it->second = std::min(it->second, pair.input_index);
  }
  std::vector<int64_t> scans;
  if (next.empty()) return scans;
  scans.push_back(next.begin()->first);
  for (auto it = next.begin(); it != next.end(); it = next.find(scans.back())) {
    scans.push_back(it->second);
  }
  return scans;
}

int Chain(const std::string& pairs_path, const std::string& output) {
  std::string error;
  if (!tools::RefuseGivenFlags(
          kEvalFlags, "does not apply to 'mlndt_eval chain'", &error)) {
    return Refuse(error);
  }
  std::map<std::string, ReferencePair> pairs;
  if (!ReadReferencePairs(pairs_path, &pairs, &error)) return Refuse(error);
  const std::vector<int64_t> scans = ChainedScans(pairs);
  if (scans.size() < 2) {
    return Fail(pairs_path + ": no pair \"i_j\" (i < j) to chain");
  }
  std::vector<Isometry3d> poses = {Isometry3d::Identity()};
  for (size_t k = 1; k < scans.size(); ++k) {
    const ReferencePair& pair =
        pairs.at(ReferencePairKey(scans[k - 1], scans[k]));
    poses.push_back(poses.back() * pair.reference_from_input);
  }
  if (!WriteKittiPoses(output, poses, &error)) return Fail(error);
  const bool gaps =
      scans.back() - scans.front() + 1 != static_cast<int64_t>(scans.size());
  std::string list;
  for (size_t k = 0; gaps && k < scans.size(); ++k) {
    list += (k ? ", " : ": ") + std::to_string(scans[k]);
  }
  std::printf("chained %zu poses (scans %lld..%lld%s) from %s -> %s\n",
              poses.size(),
              static_cast<long long>(scans.front()),
              static_cast<long long>(scans.back()),
              list.c_str(),
              pairs_path.c_str(),
              output.c_str());
  return 0;
}

// ---- evaluation -----------------------------------------------------------

struct EvalFlags {
  bool detect_estimate = true;
  TrajectoryFormat estimate_format = TrajectoryFormat::KITTI;
  bool detect_reference = true;
  TrajectoryFormat reference_format = TrajectoryFormat::KITTI;
  TrajectoryAlignment alignment = TrajectoryAlignment::SE3;
  enum class Association {
    AUTO,
    INDEX,
    TIMESTAMP
  } association = Association::AUTO;
  KittiSegmentOptions segments;
  std::vector<std::string> estimates;
};

bool ParseFlags(EvalFlags* flags, std::string* error) {
  if (!tools::CheckOutputFile("output_json", FLAGS_output_json, error)) {
    return false;
  }
  if (FLAGS_reference.empty() || FLAGS_estimate.empty()) {
    *error =
        "give --reference=FILE and --estimate=FILE[,FILE...]. Usage: "
        "mlndt_eval --reference=gt.txt --estimate=traj.txt | mlndt_eval "
        "chain PAIRS.json OUT.txt";
    return false;
  }
  std::stringstream list(FLAGS_estimate);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) {
      *error = "--estimate=" + FLAGS_estimate + ": an empty file name";
      return false;
    }
    flags->estimates.push_back(item);
  }
  if (!tools::ParseTrajectoryFormatFlag("format",
                                        FLAGS_format,
                                        &flags->detect_estimate,
                                        &flags->estimate_format,
                                        error) ||
      !tools::ParseTrajectoryFormatFlag("reference_format",
                                        FLAGS_reference_format,
                                        &flags->detect_reference,
                                        &flags->reference_format,
                                        error)) {
    return false;
  }
  if (!StringToTrajectoryAlignment(FLAGS_alignment, &flags->alignment)) {
    *error = "--alignment=" + FLAGS_alignment +
             ": expected se3, sim3, first_pose or none";
    return false;
  }
  if (FLAGS_delta < 1) {
    *error = "--delta must be >= 1";
    return false;
  }
  if (FLAGS_association == "auto") {
    flags->association = EvalFlags::Association::AUTO;
  } else if (FLAGS_association == "index") {
    flags->association = EvalFlags::Association::INDEX;
  } else if (FLAGS_association == "timestamp") {
    flags->association = EvalFlags::Association::TIMESTAMP;
  } else {
    *error = "--association=" + FLAGS_association +
             ": expected auto, index or timestamp";
    return false;
  }
  if (!(FLAGS_max_time_difference > 0.0)) {
    *error = "--max_time_difference must be > 0 [s]";
    return false;
  }
  std::vector<double> lengths;
  if (!tools::ParseNumberList(FLAGS_segment_lengths, &lengths) ||
      lengths.empty() ||
      std::any_of(lengths.begin(), lengths.end(), [](double l) {
        return !(l > 0.0);
      })) {
    *error = "--segment_lengths=" + FLAGS_segment_lengths +
             ": expected comma-separated lengths > 0 [m]";
    return false;
  }
  std::vector<double> sorted = lengths;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    *error = "--segment_lengths=" + FLAGS_segment_lengths +
             ": a length is given twice";
    return false;
  }
  flags->segments.lengths_m = lengths;
  if (FLAGS_segment_step < 1) {
    *error = "--segment_step must be >= 1";
    return false;
  }
  flags->segments.first_frame_step = FLAGS_segment_step;
  return true;
}

// Stamps the poses of a KITTI reference with --reference_times.
bool StampReference(Trajectory* reference, std::string* error) {
  std::vector<double> stamps;
  if (!ReadScanTimes(FLAGS_reference_times, &stamps, error)) return false;
  if (stamps.size() != reference->size()) {
    *error = FLAGS_reference_times + " has " + std::to_string(stamps.size()) +
             " stamps for " + std::to_string(reference->size()) + " poses";
    return false;
  }
  Trajectory stamped;
  for (size_t k = 0; k < stamps.size(); ++k) {
    stamped.Add(stamps[k], reference->world_from_sensor(k));
  }
  *reference = stamped;
  return true;
}

bool ReadOne(const std::string& path,
             bool detect,
             TrajectoryFormat given,
             const std::string& calib,
             Trajectory* trajectory,
             TrajectoryFormat* format,
             std::string* error) {
  *format = given;
  if (detect && !DetectTrajectoryFormat(path, format, error)) return false;
  if (!ReadTrajectory(path, *format, trajectory, error)) return false;
  if (calib.empty()) return true;
  Isometry3d cam0_from_velo;
  if (!ReadKittiCalibTr(calib, &cam0_from_velo, error)) return false;
  Trajectory converted;
  for (size_t k = 0; k < trajectory->size(); ++k) {
    converted.Add(trajectory->timestamp_s(k),
                  cam0_from_velo.inverse() * trajectory->world_from_sensor(k) *
                      cam0_from_velo);
  }
  *trajectory = converted;
  return true;
}

struct EstimateResult {
  std::string path;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  std::string association;
  size_t poses = 0;
  size_t pairs = 0;
  double path_length_m = 0.0;  // Of the reference over the pairs.
  AteSummary ate;
  RpeSummary rpe;
  size_t rpe_pairs = 0;
  KittiSegmentSummary kitti;
};

// `estimate` was read from result->path in result->format.
bool Evaluate(const EvalFlags& flags,
              const Trajectory& reference,
              bool reference_timed,
              const Trajectory& estimate,
              EstimateResult* result,
              std::string* error) {
  result->poses = estimate.size();
  const bool estimate_timed = result->format == TrajectoryFormat::TUM &&
                              !TumStampsAreScanIndices(result->path);
  bool by_time = false;
  switch (flags.association) {
    case EvalFlags::Association::AUTO:
      by_time = estimate_timed && reference_timed;
      break;
    case EvalFlags::Association::INDEX:
      break;
    case EvalFlags::Association::TIMESTAMP:
      if (!estimate_timed || !reference_timed) {
        *error = (estimate_timed ? FLAGS_reference : result->path) +
                 ": no time stamps (KITTI, or a TUM file whose header says "
                 "its stamps are scan indices): --association=timestamp "
                 "needs stamps on both sides";
        return false;
      }
      by_time = true;
      break;
  }
  result->association = by_time ? "timestamp" : "index";
  const AssociatedPoses pairs =
      by_time
          ? AssociateByTimestamp(reference, estimate, FLAGS_max_time_difference)
          : AssociateByIndex(reference, estimate);
  result->pairs = pairs.size();
  if (pairs.size() == 0) {
    *error = result->path + ": no pose pairs with the reference (" +
             result->association + " association)";
    return false;
  }
  const std::vector<double> distances = PathDistancesM(pairs.reference);
  result->path_length_m = distances.back();
  AteOptions ate;
  ate.alignment = flags.alignment;
  if (!ComputeAte(ate, pairs.reference, pairs.estimate, &result->ate, error)) {
    *error = result->path + ": " + *error;
    return false;
  }
  RpeOptions rpe;
  rpe.delta = FLAGS_delta;
  if (pairs.size() > static_cast<size_t>(FLAGS_delta)) {
    if (!ComputeRpe(
            rpe, pairs.reference, pairs.estimate, &result->rpe, error)) {
      *error = result->path + ": " + *error;
      return false;
    }
    result->rpe_pairs = pairs.size() - static_cast<size_t>(FLAGS_delta);
  }
  if (!ComputeKittiSegmentErrors(flags.segments,
                                 pairs.reference,
                                 pairs.estimate,
                                 &result->kitti,
                                 error)) {
    *error = result->path + ": " + *error;
    return false;
  }
  return true;
}

// One estimate's entry of --output_json (docs/json_schema.md, "mlndt_eval").
tools::Json ResultJson(const EstimateResult& r) {
  using tools::Number;
  tools::Json lengths = tools::Json::array();
  for (const KittiLengthErrors& l : r.kitti.lengths) {
    lengths.push_back(
        {{"length_m", Number(l.length_m)},
         {"segments", l.num_segments},
         {"translation_error_percent", Number(l.translation_error_percent)},
         {"rotation_error_deg_per_m", Number(l.rotation_error_deg_per_m)}});
  }
  const bool has_rpe = r.rpe_pairs > 0;
  const double nan = std::nan("");
  return {
      {"file", r.path},
      {"format", TrajectoryFormatToString(r.format)},
      {"association", r.association},
      {"poses", r.poses},
      {"pairs", r.pairs},
      {"path_length_m", Number(r.path_length_m)},
      {"ate",
       {{"rmse_m", Number(r.ate.rmse_m)},
        {"mean_m", Number(r.ate.errors.mean)},
        {"median_m", Number(r.ate.errors.median)},
        {"max_m", Number(r.ate.errors.max)},
        {"scale", Number(r.ate.reference_from_estimate.scale)}}},
      {"rpe",
       {{"pairs", r.rpe_pairs},
        {"translation_rmse_m",
         Number(has_rpe ? r.rpe.translation_rmse_m : nan)},
        {"translation_mean_m",
         Number(has_rpe ? r.rpe.translation_m.mean : nan)},
        {"translation_max_m", Number(has_rpe ? r.rpe.translation_m.max : nan)},
        {"rotation_rmse_deg", Number(has_rpe ? r.rpe.rotation_rmse_deg : nan)},
        {"rotation_mean_deg", Number(has_rpe ? r.rpe.rotation_deg.mean : nan)},
        {"rotation_max_deg", Number(has_rpe ? r.rpe.rotation_deg.max : nan)}}},
      {"kitti",
       {{"segments", r.kitti.segments.size()},
        {"translation_error_percent",
         Number(r.kitti.translation_error_percent)},
        {"rotation_error_deg_per_m", Number(r.kitti.rotation_error_deg_per_m)},
        {"lengths", lengths}}}};
}

int Run() {
  EvalFlags flags;
  std::string error;
  if (!ParseFlags(&flags, &error)) return Refuse(error);
  Trajectory reference;
  TrajectoryFormat reference_format;
  if (!ReadOne(FLAGS_reference,
               flags.detect_reference,
               flags.reference_format,
               FLAGS_reference_calib,
               &reference,
               &reference_format,
               &error)) {
    return Refuse("--reference: " + error);
  }
  if (!FLAGS_reference_times.empty()) {
    if (reference_format != TrajectoryFormat::KITTI) {
      return Refuse(
          "--reference_times applies to a KITTI --reference (a TUM "
          "file has its own stamps)");
    }
    if (!StampReference(&reference, &error)) {
      return Refuse("--reference_times=" + error);
    }
  }
  const bool reference_timed = !FLAGS_reference_times.empty() ||
                               (reference_format == TrajectoryFormat::TUM &&
                                !TumStampsAreScanIndices(FLAGS_reference));
  std::vector<EstimateResult> results(flags.estimates.size());
  std::vector<Trajectory> estimates(flags.estimates.size());
  for (size_t i = 0; i < flags.estimates.size(); ++i) {
    results[i].path = flags.estimates[i];
    if (!ReadOne(results[i].path,
                 flags.detect_estimate,
                 flags.estimate_format,
                 "",
                 &estimates[i],
                 &results[i].format,
                 &error)) {
      return Refuse(error);
    }
    // Pairing by index needs equal lengths; a common prefix only when
    // asked for with --association=index.
    const bool by_time =
        flags.association == EvalFlags::Association::TIMESTAMP ||
        (flags.association == EvalFlags::Association::AUTO &&
         results[i].format == TrajectoryFormat::TUM &&
         reference_format == TrajectoryFormat::TUM);
    if (!by_time && flags.association == EvalFlags::Association::AUTO &&
        estimates[i].size() != reference.size()) {
      return Refuse(
          results[i].path + " has " + std::to_string(estimates[i].size()) +
          " poses, --reference " + std::to_string(reference.size()) +
          ": poses are paired by index, so the lengths must match "
          "(--association=index evaluates the first " +
          std::to_string(std::min(estimates[i].size(), reference.size())) +
          " explicitly; TUM files pair by timestamp)");
    }
  }
  for (size_t i = 0; i < flags.estimates.size(); ++i) {
    if (!Evaluate(flags,
                  reference,
                  reference_timed,
                  estimates[i],
                  &results[i],
                  &error)) {
      return Fail(error);
    }
  }

  std::printf(
      "reference: %s (%s, %zu poses); ATE after %s alignment, RPE "
      "over %d frame(s)\n",
      FLAGS_reference.c_str(),
      TrajectoryFormatToString(reference_format),
      reference.size(),
      FLAGS_alignment.c_str(),
      FLAGS_delta);
  std::printf(
      "| estimate | format | pairs | length [m] | ATE rmse [m] | ATE mean [m] "
      "| ATE max [m] | RPE t rmse [m] | RPE r rmse [deg] | KITTI t [%%] | "
      "KITTI r [deg/m] |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const EstimateResult& r : results) {
    const bool has_rpe = r.rpe_pairs > 0;
    std::printf("| %s | %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                r.path.c_str(),
                TrajectoryFormatToString(r.format),
                r.pairs,
                tools::Fmt(r.path_length_m, 2).c_str(),
                tools::Fmt(r.ate.rmse_m, 4).c_str(),
                tools::Fmt(r.ate.errors.mean, 4).c_str(),
                tools::Fmt(r.ate.errors.max, 4).c_str(),
                tools::Fmt(has_rpe ? r.rpe.translation_rmse_m : NAN, 4).c_str(),
                tools::Fmt(has_rpe ? r.rpe.rotation_rmse_deg : NAN, 4).c_str(),
                tools::Fmt(r.kitti.translation_error_percent, 3).c_str(),
                tools::Fmt(r.kitti.rotation_error_deg_per_m, 5).c_str());
  }
  for (const EstimateResult& r : results) {
    if (r.kitti.lengths.empty()) {
      std::printf(
          "%s: KITTI segments: none (the reference path is %.1f m, shorter "
          "than %g m)\n",
          r.path.c_str(),
          r.path_length_m,
          *std::min_element(flags.segments.lengths_m.begin(),
                            flags.segments.lengths_m.end()));
      continue;
    }
    std::printf("%s: KITTI segments by length:", r.path.c_str());
    for (const KittiLengthErrors& l : r.kitti.lengths) {
      std::printf(" %g m (%zu): %.3f %% %.5f deg/m;",
                  l.length_m,
                  l.num_segments,
                  l.translation_error_percent,
                  l.rotation_error_deg_per_m);
    }
    std::printf("\n");
  }
  if (!FLAGS_output_json.empty()) {
    tools::Json estimates = tools::Json::array();
    for (const EstimateResult& r : results) estimates.push_back(ResultJson(r));
    tools::Json json = tools::ToolJson(kTool);
    json["reference"] = FLAGS_reference;
    json["reference_format"] = TrajectoryFormatToString(reference_format);
    json["reference_poses"] = reference.size();
    json["alignment"] = TrajectoryAlignmentToString(flags.alignment);
    json["delta"] = FLAGS_delta;
    json["estimates"] = estimates;
    if (!tools::WriteJsonFile(FLAGS_output_json, json, &error)) {
      return Fail(error);
    }
  }
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  const char* usage =
      "Evaluates trajectories (KITTI or TUM) against a reference: ATE, RPE, "
      "KITTI segment errors.\n"
      "  mlndt_eval --reference=FILE --estimate=FILE[,FILE...] "
      "[--alignment=se3]\n"
      "  mlndt_eval chain reference_pairs.json poses.txt";
  if (!mlndt::tools::StartTool(usage, false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  if (argc > 1 && std::string(argv[1]) == "chain") {
    if (argc != 4) {
      std::cerr << "mlndt_eval: usage: mlndt_eval chain PAIRS.json OUT.txt\n";
      return mlndt::tools::kExitUsage;
    }
    return mlndt::Chain(argv[2], argv[3]);
  }
  if (argc > 1) {
    std::cerr << "mlndt_eval: unexpected argument '" << argv[1]
              << "' (flags are --name=value; the one subcommand is 'chain "
                 "PAIRS OUT')\n";
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
