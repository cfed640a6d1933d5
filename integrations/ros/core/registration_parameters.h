#pragma once

// The registration's parameters of a node, as mlndt_odometry and
// mlndt_localize take them as flags (tools/cli/registration_flags.h):
// ~preset (default | paper) first, then one parameter per ML-NDT flag made
// from RegistrationOptionsTable (option_flags.h names them: ~sampling,
// ~backend, ~newton_*, ~lm_*, ~finest_cell_size_m, ...), and
// ~initial_uncertainty=translation_m,rotation_deg where the tool has it.

#include <functional>
#include <string>

#include "integrations/ros/core/option_parameters.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace ros_core {

// Adds a parameter for every ML-NDT flag (not conventional NDT's own)
// whose RegistrationOptions path `keep` accepts, setting that path of root
// `root` (a RegistrationOptions).
void AddRegistrationParameters(
    int root,
    const std::function<bool(const std::string& path)>& keep,
    OptionParameters* parameters);

// The RegistrationOptions ~preset names: default (*options as the node
// starts from them: the library's, the odometry's OdometryRegistrationOptions)
// or paper (PaperRegistrationOptions); false with *error for another value.
bool RegistrationPresetFromParameters(const ParameterSource& source,
                                      RegistrationOptions* options,
                                      std::string* error);

// ~initial_uncertainty=translation_m,rotation_deg (as the tools' flag) into
// options->initial_uncertainty when given; false with *error on a bad text.
bool InitialUncertaintyFromParameters(const ParameterSource& source,
                                      RegistrationOptions* options,
                                      std::string* error);

}  // namespace ros_core
}  // namespace mlndt
