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

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "lab/eval/dataset.h"
#include "lab/eval/statistics.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/atomic_file.h"
#include "mlndt/common/pose.h"
#include "tools/common/list_flags.h"
#include "tools/common/output_files.h"
#include "tools/common/pose_flags.h"
#include "tools/common/registration_flags.h"
#include "tools/common/start_layer_check.h"
#include "tools/common/tool_main.h"
#include "tools/common/verdict_counts.h"

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

// The initial guess of run k and its label: the identity, or the truth
// pushed off by perturbation k in the reference frame.
Isometry3d InitialGuess(const std::vector<Vector6d>& perturbations,
                        size_t k,
                        const Isometry3d& truth,
                        std::string* label) {
  if (perturbations.empty()) {
    *label = "identity";
    return Isometry3d::Identity();
  }
  std::ostringstream l;
  const Vector6d& p = perturbations[k];
  l << "gt+(" << p(0) << "," << p(1) << "," << p(2) << "," << p(3) * kRadToDeg
    << "," << p(4) * kRadToDeg << "," << p(5) * kRadToDeg << ")";
  *label = l.str();
  return PoseVectorToIsometry(perturbations[k]) * truth;
}

// Registers scan j onto scan i from `initial`, prints the table line and
// the CSV row; true on success.
bool RegisterAndPrint(const RegistrationOptions& options,
                      const std::vector<PointCloud>& scans,
                      size_t i,
                      size_t j,
                      size_t gap,
                      const Isometry3d& truth,
                      const Isometry3d& initial,
                      const std::string& label,
                      std::ostringstream* csv,  // nullptr: no CSV.
                      std::vector<double>* times,
                      tools::VerdictCounts* verdicts) {
  RegistrationSummary summary;
  Register(options, scans[i], scans[j], initial, &summary);
  verdicts->Add(summary.termination_type);
  const double et = TranslationErrorM(truth, summary.reference_from_input);
  const double er =
      RotationErrorRad(truth, summary.reference_from_input) * kRadToDeg;
  const bool ok = summary.IsSolutionUsable() &&
                  et < FLAGS_max_translation_error &&
                  er < FLAGS_max_rotation_error;
  times->push_back(summary.total_time_s * 1e3);
  std::printf("%-4zu %-4zu %-3zu %-24s %10.4f %10.4f %4s %5d %8.1f\n",
              i,
              j,
              gap,
              label.c_str(),
              et,
              er,
              ok ? "yes" : "NO",
              summary.num_iterations,
              summary.total_time_s * 1e3);
  if (csv != nullptr) {
    *csv << i << "," << j << "," << gap << ",\"" << label << "\"," << et << ","
         << er << "," << ok << ","
         << TerminationTypeToString(summary.termination_type) << ","
         << summary.num_iterations << "," << summary.total_time_s * 1e3 << "\n";
  }
  return ok;
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
  if (poses.size() < paths.size()) {
    return tools::Refuse(kTool,
                         FLAGS_gt_poses + " has " +
                             std::to_string(poses.size()) + " poses for " +
                             std::to_string(paths.size()) + " scans");
  }
  std::vector<double> gaps;
  if (!tools::ParseNumberList(FLAGS_gaps, &gaps) || gaps.empty()) {
    return tools::Refuse(
        kTool,
        "--gaps=" + FLAGS_gaps +
            ": expected comma-separated frame gaps (e.g. 1,2,5)");
  }
  for (const double gap : gaps) {
    // A gap of 0 would register every scan onto itself.
    if (!(gap >= 1.0) || gap != std::floor(gap)) {
      return tools::Refuse(
          kTool,
          "--gaps=" + FLAGS_gaps + ": a gap is a whole number of frames >= 1");
    }
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
  if (!FLAGS_output_csv.empty()) {
    csv << "reference,input,gap,perturbation,translation_error_m,rotation_"
           "error_deg,success,"
           "termination,iterations,time_ms\n";
  }
  std::printf("%-4s %-4s %-3s %-24s %10s %10s %4s %5s %8s\n",
              "ref",
              "in",
              "gap",
              "init",
              "err_t[m]",
              "err_r[deg]",
              "ok",
              "iters",
              "time[ms]");
  int total = 0, successes = 0;
  std::vector<double> times;
  tools::VerdictCounts verdicts;
  for (double gap_value : gaps) {
    const size_t gap = static_cast<size_t>(gap_value);
    for (size_t i = 0; i + gap < scans.size(); ++i) {
      const size_t j = i + gap;
      const Isometry3d truth =
          poses[i].inverse() * poses[j];  // reference_from_input.
      const size_t runs = std::max<size_t>(1, perturbations.size());
      for (size_t k = 0; k < runs; ++k) {
        std::string label;
        const Isometry3d initial =
            InitialGuess(perturbations, k, truth, &label);
        ++total;
        successes += RegisterAndPrint(options,
                                      scans,
                                      i,
                                      j,
                                      gap,
                                      truth,
                                      initial,
                                      label,
                                      FLAGS_output_csv.empty() ? nullptr : &csv,
                                      &times,
                                      &verdicts);
      }
    }
  }
  std::printf("success: %d / %d (%.1f %%), median time %.1f ms\n",
              successes,
              total,
              100.0 * successes / std::max(1, total),
              ComputeStats(times).median);
  std::printf("verdicts: %s\n", verdicts.Line().c_str());
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
