#include "integrations/ros/core/registration_parameters.h"

#include <vector>

#include "tools/cli/list_flags.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace ros_core {

void AddRegistrationParameters(
    int root,
    const std::function<bool(const std::string& path)>& keep,
    OptionParameters* parameters) {
  for (const tools::OptionFlag& flag : tools::OptionFlags()) {
    if (flag.mlndt_path.empty() || !keep(flag.mlndt_path)) continue;
    parameters->Add(flag.name, root, flag.mlndt_path);
  }
}

bool RegistrationPresetFromParameters(const ParameterSource& source,
                                      RegistrationOptions* options,
                                      std::string* error) {
  std::string preset = "default";
  if (!GetText(source, "preset", &preset, error)) return false;
  if (preset == "paper") {
    *options = PaperRegistrationOptions();
  } else if (preset != "default") {
    *error = "~preset=" + preset + ": expected default or paper";
    return false;
  }
  return true;
}

bool InitialUncertaintyFromParameters(const ParameterSource& source,
                                      RegistrationOptions* options,
                                      std::string* error) {
  std::string text;
  if (!GetText(source, "initial_uncertainty", &text, error)) return false;
  if (text.empty()) return true;
  std::vector<double> v;
  if (!tools::ParseNumberList(text, &v) || v.size() != 2) {
    *error = "~initial_uncertainty=" + text +
             ": expected translation_m,rotation_deg (e.g. 0.5,5)";
    return false;
  }
  InitialGuessUncertainty& u = options->initial_uncertainty;
  u.given = true;
  u.translation_m = v[0];
  u.rotation_deg = v[1];
  if (u.IsValid(error)) return true;
  *error = "~initial_uncertainty=" + text + ": " + *error;
  return false;
}

}  // namespace ros_core
}  // namespace mlndt
