#pragma once

// The localiser node's parameters, named and read as mlndt_localize's
// flags: ~map (the map file, --map), ~initial_guess (tx,ty,tz,alpha,beta,
// gamma in m and deg, R = Rx Ry Rz; --initial_guess), ~motion_model
// (LocalizerOwnOptionsTable, tools/cli/localizer_flags.h), ~preset,
// ~initial_uncertainty and the registration's ML-NDT flags but the map's
// (the map file fixes the cells: ~finest_cell_size_m and the other grid
// parameters are refused, as the tool refuses their flags), the node's
// settings (node_settings.h) and the frames.

#include <string>
#include <vector>

#include "integrations/ros/core/node_settings.h"
#include "integrations/ros/core/option_parameters.h"
#include "mlndt/common/types.h"
#include "mlndt/pipeline/localizer.h"

namespace mlndt {
namespace ros_core {

struct LocalizerNodeOptions {
  LocalizerOptions localizer;
  LocalizerNodeSettings node;
  std::string map_path;  // ~map.
  // ~initial_guess: the first scan's map_from_sensor when given; else the
  // node waits for one on the initial-pose topic.
  bool has_initial_pose = false;
  Isometry3d initial_map_from_sensor = Isometry3d::Identity();
  // ~start_layer was given (checked against the map's layers on load).
  bool start_layer_given = false;
  std::string map_frame = "map";  // ~map_frame.
  // ~odom_frame; "" = no odometry: publish map -> sensor on tf.
  std::string odom_frame = "odom";
  std::string sensor_frame;  // ~sensor_frame; "" = the clouds' frame_id.
};

// Roots: 0 LocalizerOptions (its own table), 1 its RegistrationOptions,
// 2 LocalizerNodeSettings.
const OptionParameters& LocalizerOptionParameters();
// The node's text parameters: map, initial_guess, preset,
// initial_uncertainty and the frames.
const std::vector<std::string>& LocalizerTextParameters();

// Everything from `source`, checked (every range, IsValid, no unknown or
// refused parameter, ~map given); false with *error naming the parameter.
// The map file is not read here.
bool LocalizerNodeOptionsFromParameters(const ParameterSource& source,
                                        LocalizerNodeOptions* options,
                                        std::string* error);

}  // namespace ros_core
}  // namespace mlndt
