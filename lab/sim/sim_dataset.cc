#include "lab/sim/sim_dataset.h"

#include <glog/logging.h>

#include "lab/sim/ray_caster.h"
#include "lab/sim/scenes.h"
#include "lab/sim/sim_random.h"

namespace mlndt {
namespace sim {
namespace {

bool MakeTrajectory(const SimulationOptions& options,
                    const Scene& scene,
                    SimTrajectory* trajectory,
                    std::string* error) {
  const uint64_t seed =
      DeriveSeed(options.seed,
                 "trajectory:" + options.scene + ":" + options.TrajectoryKind(),
                 0);
  if (options.TrajectoryKind() == "car") {
    return MakeCarTrajectory(
        options.car, scene.path, options.num_scans, seed, trajectory, error);
  }
  return MakeHandheldTrajectory(
      options.handheld, scene.path, options.num_scans, seed, trajectory, error);
}

// The rays of scan k: the sensor's, with a spinning sensor's elevations
// shifted by the scan's own draw when options.beam_offset_deg > 0.
std::vector<SensorRay> ScanRays(const SimDataset& dataset, size_t k) {
  const SimulationOptions& options = dataset.options;
  const double stamp_s = dataset.trajectory.stamps_s[k];
  if (options.beam_offset_deg <= 0.0 ||
      dataset.sensor.pattern != ScanPattern::SPINNING) {
    return SensorRays(dataset.sensor, stamp_s);
  }
  SimRandom random(options.seed, "beams:" + dataset.sensor.name, k);
  const double offset_deg =
      random.Uniform(-options.beam_offset_deg, options.beam_offset_deg);
  SensorModel shifted = dataset.sensor;
  for (double& angle_deg : shifted.spinning.vertical_angles_deg) {
    angle_deg += offset_deg;
  }
  return SensorRays(shifted, stamp_s);
}

bool RenderScans(const RayCaster& caster,
                 SimDataset* dataset,
                 std::string* error) {
  const SimTrajectory& trajectory = dataset->trajectory;
  for (size_t k = 0; k < trajectory.world_from_sensor.size(); ++k) {
    ScanMotion motion;
    motion.world_from_sensor = trajectory.world_from_sensor[k];
    motion.velocity = trajectory.Velocity(k);
    motion.moving = dataset->options.motion_within_scan;
    const uint64_t seed =
        DeriveSeed(dataset->options.seed, "scan:" + dataset->sensor.name, k);
    SimScan scan;
    RenderScan(
        caster, dataset->sensor, ScanRays(*dataset, k), motion, seed, &scan);
    if (scan.points.empty()) {
      *error = "scan " + std::to_string(k) + " of " +
               SimulationName(dataset->options) + " has no point";
      return false;
    }
    dataset->scans.push_back(std::move(scan));
  }
  return true;
}

}  // namespace

bool MakeSimDataset(const SimulationOptions& options,
                    SimDataset* dataset,
                    std::string* error) {
  CHECK(dataset != nullptr);
  CHECK(error != nullptr);
  *dataset = SimDataset();
  if (!options.IsValid(error)) return false;
  dataset->options = options;
  CHECK(MakeSensorModel(options.sensor, &dataset->sensor));
  ReturnOptions& returns = dataset->sensor.returns;
  if (options.range_sigma_m >= 0.0)
    returns.range_sigma_m = options.range_sigma_m;
  if (options.dropout_probability >= 0.0) {
    returns.dropout_probability = options.dropout_probability;
  }
  if (!dataset->sensor.IsValid(error) ||
      !BuildScene(options.scene,
                  DeriveSeed(options.seed, "scene", 0),
                  &dataset->scene,
                  error) ||
      !MakeTrajectory(options, dataset->scene, &dataset->trajectory, error)) {
    return false;
  }
  const std::unique_ptr<RayCaster> caster =
      RayCaster::Create(dataset->scene.mesh, error);
  if (caster == nullptr || !RenderScans(*caster, dataset, error)) return false;
  const std::vector<Isometry3d>& poses = dataset->trajectory.world_from_sensor;
  for (const int step : options.steps) {
    for (int i = 0; i + step < options.num_scans; ++i) {
      SimPair pair;
      pair.reference = i;
      pair.input = i + step;
      pair.reference_from_input = poses[i].inverse() * poses[i + step];
      pair.constraints = AnalysePairConstraints(options.constraints,
                                                *caster,
                                                dataset->sensor,
                                                dataset->scene,
                                                poses[i],
                                                poses[i + step],
                                                dataset->scans[i + step]);
      dataset->pairs.push_back(pair);
    }
  }
  return true;
}

}  // namespace sim
}  // namespace mlndt
