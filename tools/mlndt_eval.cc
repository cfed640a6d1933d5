// mlndt_eval: evaluates trajectories against a reference trajectory, with
// mlndt/eval: the absolute trajectory error (ATE) after an alignment, the
// relative pose error (RPE) over --delta frames, and the KITTI odometry
// devkit's segment errors (translation % and rotation deg/m over 100-800 m
// segments, reported for the lengths the trajectory is long enough for).
//
//   mlndt_eval --reference=gt.txt --estimate=a.txt[,b.tum,...]
//              [--alignment=se3|sim3|first_pose|none] [--delta=1]
//              [--output_json=eval.json]
//              [--segments_lengths_m=100,...] [--segments_first_frame_step=10]
//   mlndt_eval chain reference_pairs.json poses.txt
//
// Files are KITTI (12 numbers a line, the line index is the frame) or TUM
// ("t tx ty tz qx qy qz qw"); the format is detected (extension .kitti /
// .tum, else the first line) or given (--format for the estimates,
// --reference_format). Poses are paired by index (KITTI, the devkit's
// convention) or, when both have time stamps, by timestamp within
// --max_time_difference_s (--association; evo's nearest-stamp matching, so
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
// The evaluation's flags are TrajectoryEvaluationOptions' fields
// (tools/cli/trajectory_evaluation_flags.h).
//
// Exit codes: 2 on a bad flag or an input refused before any work (an
// unreadable file, trajectories of different lengths paired by index); 1
// when an evaluation fails or an output cannot be written.

#include <gflags/gflags.h>

#include <filesystem>
#include <iostream>
#include <map>

#include "lab/eval/reference_chain.h"
#include "lab/eval/reference_pairs.h"
#include "lab/eval/trajectory_evaluation.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "tools/cli/eval_output.h"
#include "tools/cli/flag_utils.h"
#include "tools/cli/json_output.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/map_inputs.h"
#include "tools/cli/output_files.h"
#include "tools/cli/tool_main.h"
#include "tools/cli/trajectory_evaluation_flags.h"

// clang-format off
DEFINE_string(reference, "", "The reference trajectory (KITTI or TUM)");
DEFINE_string(estimate, "", "Comma-separated trajectory files to evaluate (KITTI or TUM)");
DEFINE_string(format, "auto", "Format of the --estimate files: auto | kitti | tum");
DEFINE_string(reference_format, "auto", "Format of --reference: auto | kitti | tum");
DEFINE_string(reference_times, "", "Time stamps of a KITTI --reference: a file of one stamp [s] "
              "per pose (times.txt); then TUM estimates are associated by time");
DEFINE_string(reference_calib, "", "KITTI calib.txt: --reference holds camera (cam0) poses, "
              "converted into the Velodyne frame with its Tr line");
DEFINE_string(output_json, "", "Also write the results as JSON to this file");
// clang-format on

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_eval";

const std::vector<std::string> kEvalFlags = {"reference",
                                             "estimate",
                                             "format",
                                             "reference_format",
                                             "reference_calib",
                                             "alignment",
                                             "delta",
                                             "association",
                                             "max_time_difference_s",
                                             "segments_lengths_m",
                                             "segments_first_frame_step",
                                             "output_json"};

// ---- chain --------------------------------------------------------------

int Chain(const std::string& pairs_path, const std::string& output) {
  std::string error;
  if (!tools::RefuseGivenFlags(
          kEvalFlags, "does not apply to 'mlndt_eval chain'", &error)) {
    return tools::Refuse(kTool, error);
  }
  // OUT never replaces the pairs file (a link to it included).
  std::error_code ec;
  if (std::filesystem::equivalent(pairs_path, output, ec)) {
    return tools::Refuse(kTool,
                         "chain: OUT=" + output + " is the pairs file " +
                             pairs_path +
                             " (an output never replaces an "
                             "input)");
  }
  if (!CheckWritableFilePath(output, &error)) {
    return tools::Refuse(kTool, "chain: OUT=" + output + ": " + error);
  }
  std::map<std::string, ReferencePair> pairs;
  if (!ReadReferencePairs(pairs_path, &pairs, &error)) {
    return tools::Refuse(kTool, error);
  }
  const ReferenceChain chain = ChainReferencePairs(pairs);
  if (chain.scans.size() < 2) {
    return tools::Fail(kTool,
                       pairs_path + ": no pair \"i_j\" (i < j) to chain");
  }
  if (!WriteKittiPoses(output, chain.poses, &error)) {
    return tools::Fail(kTool, error);
  }
  tools::PrintChain(chain, pairs_path, output);
  return 0;
}

// ---- evaluation -----------------------------------------------------------

struct EvalFlags {
  TrajectoryFiles files;
  TrajectoryEvaluationOptions options;
};

// --reference, --estimate and the two format flags.
bool ParseFileFlags(EvalFlags* flags, std::string* error) {
  if (FLAGS_reference.empty() || FLAGS_estimate.empty()) {
    *error =
        "give --reference=FILE and --estimate=FILE[,FILE...]. Usage: "
        "mlndt_eval --reference=gt.txt --estimate=traj.txt | mlndt_eval "
        "chain PAIRS.json OUT.txt";
    return false;
  }
  flags->files.reference = FLAGS_reference;
  flags->files.reference_calib = FLAGS_reference_calib;
  flags->files.reference_times = FLAGS_reference_times;
  if (!tools::SplitFileList(
          "--estimate", FLAGS_estimate, &flags->files.estimates, error)) {
    return false;
  }
  return tools::ParseTrajectoryFormatFlag("format",
                                          FLAGS_format,
                                          &flags->files.detect_estimate,
                                          &flags->files.estimate_format,
                                          error) &&
         tools::ParseTrajectoryFormatFlag("reference_format",
                                          FLAGS_reference_format,
                                          &flags->files.detect_reference,
                                          &flags->files.reference_format,
                                          error);
}

bool ParseFlags(EvalFlags* flags, std::string* error) {
  if (!tools::CheckOutputFile("output_json", FLAGS_output_json, error) ||
      !ParseFileFlags(flags, error)) {
    return false;
  }
  // The lengths' own check first (positive, none twice), for its message.
  const std::string lengths = "segments_lengths_m";
  std::vector<double> parsed;
  if (tools::FlagGiven(lengths) &&
      !tools::ParseLengthList(tools::GivenFlagName(lengths),
                              tools::FlagText(lengths),
                              &parsed,
                              error)) {
    return false;
  }
  return tools::TrajectoryEvaluationFlags().Apply(&flags->options, error);
}

int Run() {
  EvalFlags flags;
  std::string error;
  EvaluationReference reference;
  std::vector<Trajectory> estimates;
  std::vector<TrajectoryEvaluation> results;
  if (!ParseFlags(&flags, &error) || !ReadTrajectoryFiles(flags.options,
                                                          flags.files,
                                                          &reference,
                                                          &estimates,
                                                          &results,
                                                          &error)) {
    return tools::Refuse(kTool, error);
  }
  for (size_t i = 0; i < estimates.size(); ++i) {
    if (!EvaluateTrajectory(
            flags.options, reference, estimates[i], &results[i], &error)) {
      return tools::Fail(kTool, error);
    }
  }
  tools::PrintEvaluations(
      flags.options, tools::FlagText("alignment"), reference, results);
  if (!FLAGS_output_json.empty() &&
      !tools::WriteJsonFile(
          FLAGS_output_json,
          tools::EvaluationsJson(flags.options, reference, results),
          &error)) {
    return tools::Fail(kTool, error);
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
  mlndt::tools::RefuseUnreadFlags(
      {"bag", "topic", "times", "calib", "poses_are_camera"},
      "does not apply to mlndt_eval (it reads trajectory files: stamp a KITTI "
      "--reference with --reference_times, convert camera poses with "
      "--reference_calib)");
  if (!mlndt::tools::StartTool(usage, false, &argc, &argv)) {
    return mlndt::tools::kExitUsage;
  }
  const auto arguments =
      mlndt::tools::ParseSubcommand("mlndt_eval",
                                    argc,
                                    argv,
                                    "chain",
                                    2,
                                    "mlndt_eval chain PAIRS.json OUT.txt",
                                    "chain PAIRS OUT");
  if (arguments == mlndt::tools::ToolArguments::MISUSE) {
    return mlndt::tools::kExitUsage;
  }
  if (arguments == mlndt::tools::ToolArguments::SUBCOMMAND)
    return mlndt::Chain(argv[2], argv[3]);
  return mlndt::Run();
}
