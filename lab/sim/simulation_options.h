#pragma once

// What one simulated data set is made of: a sensor, a scene and a
// trajectory kind (by name), a seed, how many scans, which pairs, and the
// generators' options. Everything in the data set follows from these: the
// same options give the same bytes.
//
// Seeds: the scene comes from the seed alone (every sensor and trajectory
// of a seed sees the same scene); the trajectory from the seed, the scene
// and its kind (every sensor of a seed and scene travels the same path); each
// scan's noise from the seed, the sensor and the scan's index. Train / test:
// thresholds and defaults are chosen on seeds 0-999 (train) and reported on
// seeds >= 1000 (test), never the other way round.

#include <cstdint>
#include <string>
#include <vector>

#include "lab/sim/car_trajectory.h"
#include "lab/sim/handheld_trajectory.h"
#include "lab/sim/pair_constraints.h"

namespace mlndt {
namespace sim {

// Seeds below this are for training (choosing thresholds), the rest for
// testing.
constexpr uint64_t kFirstTestSeed = 1000;

struct SimulationOptions {
  std::string sensor = "hdl64";  // SensorNames() (sensor_model.h).
  std::string scene = "street";  // SceneNames() (scenes.h).
  // "car", "handheld", or "auto": hand-held indoors (IsIndoorScene), car
  // outdoors.
  std::string trajectory = "auto";
  uint64_t seed = 0;
  int num_scans = 4;  // In [2, 10000].
  // Pairs i -> i + step for these steps (each >= 1).
  std::vector<int> steps = {1, 2, 3};
  // The sensor moves during each sweep (scan_renderer.h).
  bool motion_within_scan = false;
  // When >= 0, replace the sensor's range noise sigma [m] / dropout
  // probability.
  double range_sigma_m = -1.0;
  double dropout_probability = -1.0;
  // Diagnostic (lab/records/bias.md): when > 0, a spinning sensor's laser
  // elevations are shifted in each scan by its own draw, uniform in
  // [-beam_offset_deg, +beam_offset_deg], so the rings of two scans do not
  // coincide (a real sensor's do); in [0, 10] [deg]. 0 for no shift.
  double beam_offset_deg = 0.0;
  CarTrajectoryOptions car;
  HandheldTrajectoryOptions handheld;
  PairConstraintOptions constraints;

  bool IsValid(std::string* error) const;
  // "car" or "handheld" (resolves "auto").
  std::string TrajectoryKind() const;
};

// "<sensor>_<scene>_<trajectory kind>_<seed>", e.g. "hdl64_street_car_1000".
std::string SimulationName(const SimulationOptions& options);

}  // namespace sim
}  // namespace mlndt
