#pragma once

// The odometry node's parameters, named and read as mlndt_odometry's
// flags: OdometryOptions' own fields (tools/cli/odometry_flags.h:
// ~local_map_max_keyframes, ~gate_factor, ~confirmation_enabled, ...), the
// registration's ML-NDT flags over OdometryRegistrationOptions()
// (registration_parameters.h; the grid flags shape the local map, as
// --finest_cell_size_m does for the tool), ~preset, the node's settings
// (node_settings.h) and the frames. Equal parameters and flags give equal
// OdometryOptions.

#include <string>
#include <vector>

#include "integrations/ros/core/node_settings.h"
#include "integrations/ros/core/option_parameters.h"
#include "mlndt/odometry/odometry_options.h"

namespace mlndt {
namespace ros_core {

struct OdometryNodeOptions {
  OdometryOptions odometry;
  OdometryNodeSettings node;
  std::string odom_frame = "odom";  // ~odom_frame.
  // ~sensor_frame; "" = each cloud's header.frame_id.
  std::string sensor_frame;
};

// Roots: 0 OdometryOptions (its own table), 1 its RegistrationOptions,
// 2 OdometryNodeSettings.
const OptionParameters& OdometryOptionParameters();
// The node's text parameters: preset, odom_frame, sensor_frame.
const std::vector<std::string>& OdometryTextParameters();

// Everything from `source`, checked (every range, IsValid, no unknown
// parameter); false with *error naming the parameter.
bool OdometryNodeOptionsFromParameters(const ParameterSource& source,
                                       OdometryNodeOptions* options,
                                       std::string* error);

}  // namespace ros_core
}  // namespace mlndt
