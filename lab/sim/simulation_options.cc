#include "lab/sim/simulation_options.h"

#include <algorithm>

#include "lab/sim/scenes.h"
#include "lab/sim/sensor_model.h"

namespace mlndt {
namespace sim {

bool SimulationOptions::IsValid(std::string* error) const {
  SensorModel model;
  if (!MakeSensorModel(sensor, &model)) {
    *error = "unknown sensor '" + sensor + "'";
    return false;
  }
  const std::vector<std::string> scenes = SceneNames();
  if (std::find(scenes.begin(), scenes.end(), scene) == scenes.end()) {
    *error = "unknown scene '" + scene + "'";
    return false;
  }
  if (trajectory != "car" && trajectory != "handheld" && trajectory != "auto") {
    *error =
        "trajectory must be car, handheld or auto, not '" + trajectory + "'";
    return false;
  }
  if (num_scans < 2 || num_scans > 10000) {
    *error = "num_scans must be in [2, 10000]";
    return false;
  }
  if (steps.empty()) {
    *error = "no steps";
    return false;
  }
  for (const int step : steps) {
    if (step < 1) {
      *error = "a step < 1";
      return false;
    }
  }
  if (range_sigma_m > 10.0 || dropout_probability >= 1.0) {
    *error = "range_sigma_m must be <= 10 and dropout_probability < 1";
    return false;
  }
  if (!(constraints.tolerance_m > 0.0 && constraints.tolerance_deg > 0.0 &&
        constraints.visibility_m > 0.0 && constraints.max_points >= 1)) {
    *error = "constraints: tolerances, visibility_m and max_points must be > 0";
    return false;
  }
  if (!(beam_offset_deg >= 0.0 && beam_offset_deg <= 10.0)) {
    *error = "beam_offset_deg must be in [0, 10]";
    return false;
  }
  return car.IsValid(error) && handheld.IsValid(error);
}

std::string SimulationOptions::TrajectoryKind() const {
  if (trajectory != "auto") return trajectory;
  return IsIndoorScene(scene) ? "handheld" : "car";
}

std::string SimulationName(const SimulationOptions& options) {
  return options.sensor + "_" + options.scene + "_" + options.TrajectoryKind() +
         "_" + std::to_string(options.seed);
}

}  // namespace sim
}  // namespace mlndt
