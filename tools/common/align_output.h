#pragma once

// What mlndt_align prints and writes about one registration: the
// per-iteration trace, the 4x4 pose and the result JSON
// (docs/json_schema.md).

#include <string>

#include "lab/runs/matcher.h"
#include "mlndt/registration/registration_summary.h"
#include "tools/common/json_output.h"

namespace mlndt {
namespace tools {

// --trace: one line per iteration.
void PrintTrace(const RegistrationSummary& summary);

// "reference_from_input (4x4, row-major):" and the four rows.
void PrintPoseMatrix(const RegistrationSummary& summary);

// The result JSON; `expected` empty: no comparison with an expected pose.
Json AlignResultJson(const std::string& reference,
                     const std::string& input,
                     const std::string& expected,
                     Method method,
                     const RegistrationSummary& summary,
                     double peak_bytes,
                     double translation_error_m,
                     double rotation_error_deg);

}  // namespace tools
}  // namespace mlndt
