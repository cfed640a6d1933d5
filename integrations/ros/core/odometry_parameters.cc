#include "integrations/ros/core/odometry_parameters.h"

#include "integrations/ros/core/registration_parameters.h"
#include "mlndt/odometry/odometry_option_tables.h"
#include "tools/cli/odometry_flags.h"

namespace mlndt {
namespace ros_core {
namespace {

// The parameter of an odometry field: its flag, or the shared flag that
// sets it.
std::string ParameterName(const tools::TableFlags& flags,
                          const std::string& path) {
  const std::string flag = flags.FlagOf(path);
  if (!flag.empty()) return flag;
  for (const auto& [field, shared] : flags.set_by_tool_flag()) {
    if (field == path) return shared;
  }
  return "";
}

}  // namespace

const OptionParameters& OdometryOptionParameters() {
  static const OptionParameters parameters = [] {
    OptionParameters p({&OdometryOwnOptionsTable(),
                        &RegistrationOptionsTable(),
                        &OdometryNodeSettingsTable()});
    const tools::TableFlags& own = tools::OdometryFlags();
    for (const tools::TableFlags::Field& f : own.fields()) {
      const std::string name = ParameterName(own, f.path);
      if (!name.empty()) p.Add(name, 0, f.path);
    }
    AddRegistrationParameters(
        1, [](const std::string&) { return true; }, &p);
    for (const OptionField& field : OdometryNodeSettingsTable().fields()) {
      p.Add(field.name, 2, field.name);
    }
    return p;
  }();
  return parameters;
}

const std::vector<std::string>& OdometryTextParameters() {
  static const std::vector<std::string> names = {
      "preset", "odom_frame", "sensor_frame"};
  return names;
}

bool OdometryNodeOptionsFromParameters(const ParameterSource& source,
                                       OdometryNodeOptions* options,
                                       std::string* error) {
  const OptionParameters& parameters = OdometryOptionParameters();
  OdometryNodeOptions result;
  OdometryOptions& odometry = result.odometry;
  if (!CheckKnownParameters(
          source, parameters, OdometryTextParameters(), {}, error) ||
      !RegistrationPresetFromParameters(
          source, &odometry.registration, error) ||
      !parameters.Apply(
          source, {&odometry, &odometry.registration, &result.node}, error) ||
      !GetText(source, "odom_frame", &result.odom_frame, error) ||
      !GetText(source, "sensor_frame", &result.sensor_frame, error)) {
    return false;
  }
  // As mlndt_odometry: the grid flags shape the local map.
  odometry.local_map.grid = odometry.registration.grid;
  if (!odometry.registration.IsValid(error) || !odometry.IsValid(error)) {
    *error = "invalid parameters: " + *error;
    return false;
  }
  if (result.odom_frame.empty() || result.odom_frame == result.sensor_frame) {
    *error = "~odom_frame must be a frame name other than ~sensor_frame";
    return false;
  }
  *options = std::move(result);
  return true;
}

}  // namespace ros_core
}  // namespace mlndt
