#include "tools/common/align_output.h"

#include <cstdio>

#include "tools/common/verdict_flags.h"

namespace mlndt {
namespace tools {

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

void PrintPoseMatrix(const RegistrationSummary& summary) {
  std::printf("reference_from_input (4x4, row-major):\n");
  const Eigen::Matrix4d& m = summary.reference_from_input.matrix();
  for (int r = 0; r < 4; ++r) {
    std::printf(
        "%14.9f %14.9f %14.9f %14.9f\n", m(r, 0), m(r, 1), m(r, 2), m(r, 3));
  }
}

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

}  // namespace tools
}  // namespace mlndt
