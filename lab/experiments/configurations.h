#pragma once

// The configurations the report compares (issue 15): the paper's preset
// (PaperRegistrationOptions), the library's defaults (RegistrationOptions)
// and the ablation between them, one change at a time, plus the
// conventional NDT baseline. Every configuration runs single-threaded so
// that times compare.

#include <string>
#include <vector>

#include "lab/runs/matcher.h"

namespace mlndt {
namespace experiments {

struct Configuration {
  std::string key;    // For CSV files: "paper", "loss", ..., "defaults".
  std::string label;  // For the report: "paper", "+Cauchy loss", ...
  MatcherOptions options;
};

// paper → +Cauchy loss → +nearest-cell scoring → +our schedule → defaults.
// The first is the paper preset and the last the defaults, exactly; each
// step in between takes one component from the defaults.
std::vector<Configuration> AblationConfigurations();

// The first and last of the ablation.
Configuration PaperConfiguration();
Configuration DefaultConfiguration();

// Conventional NDT (NdtOptions' defaults: the paper's layer-2 cell, GBS).
Configuration NdtConfiguration();

// `c` with uniform random sampling of `fraction` of the input (in (0, 1])
// instead of GBS; key and label get the sampling appended.
Configuration WithRandomSampling(const Configuration& c, double fraction);

// One option that differs between the paper preset and the defaults: its
// value in each and the ablation step that takes the default value.
struct OptionDifference {
  std::string option;  // E.g. "objective.loss".
  std::string paper;
  std::string defaults;
  std::string step;  // The label of the ablation step that changes it.
};

// Every option of the list in configurations.cc whose value differs, in the
// order of that list. Computed from the option structs, not written down.
std::vector<OptionDifference> PaperDefaultDifferences();

}  // namespace experiments
}  // namespace mlndt
