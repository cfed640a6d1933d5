#include "integrations/ros/core/localizer_parameters.h"

#include "integrations/ros/core/registration_parameters.h"
#include "mlndt/pipeline/pipeline_option_tables.h"
#include "tools/cli/localizer_flags.h"
#include "tools/cli/map_inputs.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace ros_core {
namespace {

bool IsMapPath(const std::string& path) { return path.rfind("grid.", 0) == 0; }

// The grid parameters, refused with the tool's reason.
std::vector<std::pair<std::string, std::string>> RefusedParameters() {
  std::vector<std::pair<std::string, std::string>> refused;
  for (const tools::OptionFlag& flag : tools::OptionFlags()) {
    if (IsMapPath(flag.mlndt_path)) {
      refused.push_back({flag.name,
                         "the map file fixes the cells (build the map with "
                         "mlndt_map to change them)"});
    }
  }
  return refused;
}

// ~initial_guess in mlndt_localize's --initial_guess format.
bool InitialPoseFromParameters(const ParameterSource& source,
                               LocalizerNodeOptions* options,
                               std::string* error) {
  std::string guess;
  if (!GetText(source, "initial_guess", &guess, error)) return false;
  if (guess.empty()) return true;
  if (!tools::ParseInitialPose(guess,
                               "",
                               &options->initial_map_from_sensor,
                               &options->has_initial_pose,
                               error)) {
    // The tool's message names its flag.
    if (error->rfind("--", 0) == 0) error->replace(0, 2, "~");
    return false;
  }
  return true;
}

bool TextParameters(const ParameterSource& source,
                    LocalizerNodeOptions* options,
                    std::string* error) {
  return GetText(source, "map", &options->map_path, error) &&
         GetText(source, "map_frame", &options->map_frame, error) &&
         GetText(source, "odom_frame", &options->odom_frame, error) &&
         GetText(source, "sensor_frame", &options->sensor_frame, error) &&
         InitialPoseFromParameters(source, options, error);
}

}  // namespace

const OptionParameters& LocalizerOptionParameters() {
  static const OptionParameters parameters = [] {
    OptionParameters p({&LocalizerOwnOptionsTable(),
                        &RegistrationOptionsTable(),
                        &LocalizerNodeSettingsTable()});
    const tools::TableFlags& own = tools::LocalizerFlags();
    for (const tools::TableFlags::Field& f : own.fields()) {
      const std::string name = own.FlagOf(f.path);
      if (!name.empty()) p.Add(name, 0, f.path);
    }
    AddRegistrationParameters(
        1, [](const std::string& path) { return !IsMapPath(path); }, &p);
    for (const OptionField& field : LocalizerNodeSettingsTable().fields()) {
      p.Add(field.name, 2, field.name);
    }
    return p;
  }();
  return parameters;
}

const std::vector<std::string>& LocalizerTextParameters() {
  static const std::vector<std::string> names = {"map",
                                                 "initial_guess",
                                                 "preset",
                                                 "initial_uncertainty",
                                                 "map_frame",
                                                 "odom_frame",
                                                 "sensor_frame"};
  return names;
}

bool LocalizerNodeOptionsFromParameters(const ParameterSource& source,
                                        LocalizerNodeOptions* options,
                                        std::string* error) {
  const OptionParameters& parameters = LocalizerOptionParameters();
  LocalizerNodeOptions result;
  LocalizerOptions& localizer = result.localizer;
  if (!CheckKnownParameters(source,
                            parameters,
                            LocalizerTextParameters(),
                            RefusedParameters(),
                            error) ||
      !RegistrationPresetFromParameters(
          source, &localizer.registration, error) ||
      !parameters.Apply(
          source, {&localizer, &localizer.registration, &result.node}, error) ||
      !InitialUncertaintyFromParameters(
          source, &localizer.registration, error) ||
      !TextParameters(source, &result, error)) {
    return false;
  }
  if (!localizer.IsValid(error)) {
    *error = "invalid parameters: " + *error;
    return false;
  }
  if (result.map_path.empty()) {
    *error = "~map is not set: give the map file (mlndt_map --output)";
    return false;
  }
  if (result.map_frame.empty() || result.map_frame == result.odom_frame ||
      result.map_frame == result.sensor_frame) {
    *error =
        "~map_frame must be a frame name other than ~odom_frame and "
        "~sensor_frame";
    return false;
  }
  std::string unused, ignored;
  result.start_layer_given = source.Get("start_layer", &unused, &ignored);
  *options = std::move(result);
  return true;
}

}  // namespace ros_core
}  // namespace mlndt
