// mlndt_pairs: registers pairs of scans from a folder with ground-truth poses
// and reports accuracy and timing per pair and in total.
//
//   mlndt_pairs --scans=DIR --gt_poses=poses.txt [--gaps=1,2,3,5]
//               [--perturbations="5,0,0,0,0,0;0,0,0,0,0,30"]
//               [--output_csv=FILE]
//
// Scan j is registered onto scan i = j - gap. Poses are KITTI 12-number lines
// in the scans' own (sensor) frame, one per scan in file-name order. The
// initial guess is the identity (the paper's Z = 0), or, for each
// perturbation (tx,ty,tz [m], alpha,beta,gamma [deg]), the ground truth
// pushed off by it in the reference frame. Success: translation error below
// --max_translation_error and rotation error below --max_rotation_error.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cmath>
#include <sstream>

#include "lab/eval/dataset.h"
#include "lab/experiments/gap_pairs.h"
#include "lab/programs/pairs_output.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "tools/cli/list_flags.h"
#include "tools/cli/output_files.h"
#include "tools/cli/pose_flags.h"
#include "tools/cli/registration_flags.h"
#include "tools/cli/start_layer_check.h"
#include "tools/cli/tool_main.h"

DEFINE_string(scans, "", "Folder of scans (sorted by file name)");
DEFINE_string(gt_poses,
              "",
              "KITTI-format poses of the scans, in the scans' frame");
DEFINE_string(gaps, "1", "Comma-separated frame gaps: scan i+gap onto scan i");
DEFINE_string(perturbations,
              "",
              "';'-separated tx,ty,tz,alpha,beta,gamma offsets [m, deg] from "
              "the ground truth; "
              "empty = start from the identity");
DEFINE_double(max_translation_error, 0.2, "Success threshold [m]");
DEFINE_double(max_rotation_error, 1.0, "Success threshold [deg]");
DEFINE_string(output_csv, "", "Per-pair results as CSV");

namespace mlndt {
namespace {

constexpr char kTool[] = "mlndt_pairs";

// ';'-separated tx,ty,tz,alpha,beta,gamma offsets [m, deg].
bool ParsePerturbations(const std::string& text,
                        std::vector<Vector6d>* perturbations,
                        std::string* error) {
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    std::vector<double> v;
    if (!tools::ParseNumberList(item, &v) || v.size() != 6) {
      *error = "bad --perturbations item '" + item + "': 6 numbers needed";
      return false;
    }
    perturbations->push_back(
        PoseVectorFromDegrees(v[0], v[1], v[2], v[3], v[4], v[5]));
  }
  return true;
}

int Run() {
  if (FLAGS_scans.empty() || FLAGS_gt_poses.empty())
    return tools::Refuse(kTool, "--scans and --gt_poses are required");
  RegistrationOptions options;
  std::string error;
  if (!tools::RegistrationOptionsFromFlags(&options, &error) ||
      !tools::CheckStartLayerBeforeMap(options, &error)) {
    return tools::Refuse(kTool, error);
  }

  std::vector<std::string> paths;
  if (!ListScanFiles(
          FLAGS_scans, {FLAGS_gt_poses, FLAGS_calib}, &paths, &error)) {
    return tools::Refuse(kTool, error);
  }
  if (!tools::CheckCameraPoseFlags("--gt_poses", true, &error)) {
    return tools::Refuse(kTool, error);
  }
  std::vector<Isometry3d> poses;
  if (!ReadSequencePoses(FLAGS_gt_poses, FLAGS_calib, &poses, &error)) {
    return tools::Refuse(kTool, "--gt_poses: " + error);
  }
  if (!tools::CheckPoseCount("--gt_poses=" + FLAGS_gt_poses,
                             poses.size(),
                             paths.size(),
                             -1,
                             &error)) {
    return tools::Refuse(kTool, error);
  }
  // A gap of 0 would register every scan onto itself, one of the scans or
  // more leaves no pair.
  std::vector<std::string> items;
  std::vector<size_t> gaps;
  if (!tools::SplitList(FLAGS_gaps, &items)) {
    return tools::Refuse(
        kTool,
        "--gaps=" + FLAGS_gaps +
            ": expected comma-separated frame gaps (e.g. 1,2,5)");
  }
  if (!tools::ParseCountList(
          FLAGS_gaps, 1, paths.empty() ? 0 : paths.size() - 1, &gaps, &error)) {
    return tools::Refuse(kTool,
                         "--gaps=" + FLAGS_gaps +
                             ": a gap is a whole number of frames >= 1, "
                             "below the number of scans (" +
                             std::to_string(paths.size()) + "): " + error);
  }
  std::vector<Vector6d> perturbations;
  if (!ParsePerturbations(FLAGS_perturbations, &perturbations, &error)) {
    return tools::Refuse(kTool, error);
  }
  if (!tools::CheckOutputFile("output_csv", FLAGS_output_csv, &error)) {
    return tools::Refuse(kTool, error);
  }
  std::vector<PointCloud> scans(paths.size());
  for (size_t i = 0; i < paths.size(); ++i) {
    if (!ReadPointCloud(paths[i], &scans[i], nullptr, &error))
      return tools::Refuse(kTool, error);
  }
  std::ostringstream csv;
  if (!FLAGS_output_csv.empty()) csv << lab::PairsCsvHeader();
  lab::PrintPairsHeader();
  GapPairsOptions pairs;
  pairs.gaps = gaps;
  pairs.perturbations = perturbations;
  pairs.max_translation_error_m = FLAGS_max_translation_error;
  pairs.max_rotation_error_deg = FLAGS_max_rotation_error;
  lab::PairsTally tally;
  RunGapPairs(pairs, options, scans, poses, [&](const GapPairRun& run) {
    tally.Add(run);
    lab::PrintPairRow(run);
    if (!FLAGS_output_csv.empty()) lab::AppendPairCsvRow(run, &csv);
  });
  lab::PrintPairsTally(tally);
  if (!FLAGS_output_csv.empty() &&
      !WriteFileAtomically(FLAGS_output_csv, csv.str(), &error)) {
    return tools::Fail(kTool, error);
  }
  return tools::kExitOk;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  if (!mlndt::tools::StartTool(
          "Registers scan pairs with ground truth and reports success rates.\n"
          "An evaluation: exit 0 when the report is complete, whatever the "
          "registrations' verdicts (each row says whether its pair is right; "
          "the verdicts line counts them); 1 when the CSV cannot be written; "
          "2 for a refused flag or input.",
          false,
          &argc,
          &argv)) {
    return mlndt::tools::kExitUsage;
  }
  return mlndt::Run();
}
