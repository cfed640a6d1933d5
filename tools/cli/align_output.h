#pragma once

// What mlndt_align prints and writes about one registration: the
// per-iteration trace, the 4x4 pose and the result JSON
// (docs/json_schema.md).

#include <string>

#include "lab/runs/matcher.h"
#include "mlndt/registration/registration_summary.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace tools {

// The result JSON; `expected` empty: no comparison with an expected pose.
Json AlignResultJson(const std::string& reference,
                     const std::string& input,
                     const std::string& expected,
                     Method method,
                     const RegistrationSummary& summary,
                     double peak_bytes,
                     double translation_error_m,
                     double rotation_error_deg);

// The clouds, the summary's report, the peak memory, with `trace` the
// per-iteration table, with an `expected_path` the error against
// `expected` (*translation_error_m, *rotation_error_deg; left as they are
// without), and the 4x4 pose (for a FAILURE a line saying there is none).
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
                      double* rotation_error_deg);

// Why a result that is not accepted (AcceptedResult) is refused, naming
// the --output_cloud left unwritten.
std::string UnacceptedResultMessage(const RegistrationSummary& summary,
                                    const std::string& output_cloud);

// A cloud with fewer points than one NDT cell needs (a pose or matrix file
// given as a cloud) can give no map or no fit: refused before any work.
bool CheckCloudSizes(const MatcherOptions& options,
                     const std::string& reference_path,
                     const PointCloud& reference,
                     const std::string& input_path,
                     const PointCloud& input,
                     std::string* error);

}  // namespace tools
}  // namespace mlndt
