#include "tools/cli/align_output.h"

#include <cstdio>
#include <iostream>

#include "mlndt/common/pose.h"
#include "tools/cli/verdict_flags.h"

namespace mlndt {
namespace tools {

namespace {

// "reference_from_input (4x4, row-major):" and the four rows.
void PrintPoseMatrix(const RegistrationSummary& summary) {
  std::printf("reference_from_input (4x4, row-major):\n");
  const Eigen::Matrix4d& m = summary.reference_from_input.matrix();
  for (int r = 0; r < 4; ++r) {
    std::printf(
        "%14.9f %14.9f %14.9f %14.9f\n", m(r, 0), m(r, 1), m(r, 2), m(r, 3));
  }
}

// --trace: one line per iteration.
void PrintTrace(const RegistrationSummary& summary) {
  for (const IterationRecord& r : summary.trace) {
    std::printf("  iter %2d layer %d score %12.2f step %.2e %s\n",
                r.iteration,
                r.layer,
                r.score,
                r.step_norm,
                r.step_is_successful ? "" : "(rejected)");
  }
}

}  // namespace

Json AlignResultJson(const std::string& reference,
                     const std::string& input,
                     const std::string& expected,
                     Method method,
                     const RegistrationSummary& summary,
                     double peak_bytes,
                     double translation_error_m,
                     double rotation_error_deg) {
  Json json = ToolJson("mlndt_align");
  json["reference"] = reference;
  json["input"] = input;
  json["method"] = MethodToString(method);
  json["accepted"] = AcceptedResult(summary.termination_type);
  json["registration"] = RegistrationSummaryJson(summary, true);
  if (!expected.empty()) {
    json["expected"] = {{"file", expected},
                        {"translation_error_m", Number(translation_error_m)},
                        {"rotation_error_deg", Number(rotation_error_deg)}};
  }
  json["memory"] = {{"peak_resident_bytes", peak_bytes}};
  return json;
}

void PrintAlignResult(const std::string& reference_path,
                      size_t reference_points,
                      const std::string& input_path,
                      size_t input_points,
                      const RegistrationSummary& summary,
                      double peak_bytes,
                      bool trace,
                      const std::string& expected_path,
                      const Isometry3d& expected,
                      double* translation_error_m,
                      double* rotation_error_deg) {
  std::cout << "reference: " << reference_path << " (" << reference_points
            << " points)\n"
            << "input:     " << input_path << " (" << input_points
            << " points)\n"
            << summary.FullReport();
  std::printf(
      "  peak memory:    %.1f MB resident (the process, clouds included)\n",
      peak_bytes / 1e6);
  if (trace) PrintTrace(summary);
  if (!expected_path.empty()) {
    *translation_error_m =
        TranslationErrorM(expected, summary.reference_from_input);
    *rotation_error_deg =
        RotationErrorRad(expected, summary.reference_from_input) * kRadToDeg;
    std::printf("  vs expected:    %.4f m, %.4f deg (%s)\n",
                *translation_error_m,
                *rotation_error_deg,
                expected_path.c_str());
  }
  // A FAILURE's pose is its start, not an estimate.
  if (summary.termination_type == TerminationType::FAILURE) {
    std::printf("reference_from_input: none (FAILURE)\n");
  } else {
    PrintPoseMatrix(summary);
  }
}

std::string UnacceptedResultMessage(const RegistrationSummary& summary,
                                    const std::string& output_cloud) {
  const bool failed = summary.termination_type == TerminationType::FAILURE;
  const std::string cloud =
      output_cloud.empty()
          ? ""
          : "; --output_cloud=" + output_cloud + " not written";
  const std::string accept = failed ? "" : " (--accept_unverified accepts it)";
  const std::string what = failed ? ": the registration failed: "
                                  : ": the pose is not to be trusted: ";
  return TerminationTypeToString(summary.termination_type) + what +
         summary.message + cloud + accept;
}

bool CheckCloudSizes(const MatcherOptions& options,
                     const std::string& reference_path,
                     const PointCloud& reference,
                     const std::string& input_path,
                     const PointCloud& input,
                     std::string* error) {
  LayeredGridOptions grid;
  if (!MatcherGridOptions(options, reference, &grid, error)) return false;
  const size_t needed = static_cast<size_t>(grid.min_points_per_cell);
  for (const auto& [path, cloud] : {std::make_pair(&reference_path, &reference),
                                    std::make_pair(&input_path, &input)}) {
    if (cloud->size() < needed) {
      *error = *path + ": " + std::to_string(cloud->size()) +
               " points, fewer than one NDT cell needs (min_points_per_cell " +
               std::to_string(needed) + "); is it a point cloud?";
      return false;
    }
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
