#pragma once

// Options from the shared registration flags (option_flags.h): the matcher's
// (ML-NDT or NDT), with --preset, --method and --initial_uncertainty, and
// refusals of flags the chosen method or backend would ignore.

#include <gflags/gflags.h>

#include <string>

#include "lab/runs/matcher.h"
#include "tools/cli/option_flags.h"

DECLARE_string(preset);
DECLARE_string(method);
DECLARE_string(initial_uncertainty);

namespace mlndt {
namespace tools {

// Fills *options from --preset and the flags given on the command line;
// false with *error naming the flag for a bad value or a combination that
// would be silently ignored (e.g. --backend with --method=ndt).
bool MatcherOptionsFromFlags(MatcherOptions* options, std::string* error);

// The range filter of --min_range_m, --max_range_m and
// --saturated_range_fraction; false with *error naming the flag.
bool RangeFilterOptionsFromFlags(RangeFilterOptions* filter,
                                 std::string* error);

// The registration options of --preset and the ML-NDT flags (ML-NDT only;
// false with *error for --method=ndt), from `defaults` (the library's, or a
// tool's preset such as OdometryRegistrationOptions()) unless
// --preset=paper.
bool RegistrationOptionsFromFlags(RegistrationOptions* options,
                                  std::string* error);
bool RegistrationOptionsFromFlags(const RegistrationOptions& defaults,
                                  RegistrationOptions* options,
                                  std::string* error);

// Makes the registration flags whose field differs in `defaults` from the
// library's default show the value of `defaults` in --help (gflags'
// SET_FLAGS_DEFAULT: the flag stays not given). Call before StartTool.
void ShowRegistrationDefaults(const RegistrationOptions& defaults);

}  // namespace tools
}  // namespace mlndt
