#pragma once

// Making one simulated data set in memory: the scene, the trajectory, every
// scan rendered along it, and the pairs i -> i + step with their exact
// relative pose reference_from_input = P_i^-1 P_j (p_i = T p_j, P the
// world_from_sensor poses at the stamps) and the directions the scene
// leaves free (pair_constraints.h). dataset_files.h writes it.

#include <string>
#include <vector>

#include "lab/sim/pair_constraints.h"
#include "lab/sim/scan_renderer.h"
#include "lab/sim/scene.h"
#include "lab/sim/sensor_model.h"
#include "lab/sim/sim_trajectory.h"
#include "lab/sim/simulation_options.h"

namespace mlndt {
namespace sim {

struct SimPair {
  int reference = 0;  // i.
  int input = 0;      // j.
  Isometry3d reference_from_input = Isometry3d::Identity();
  PairConstraints constraints;
};

struct SimDataset {
  SimulationOptions options;
  SensorModel sensor;  // With the options' overrides applied.
  Scene scene;
  SimTrajectory trajectory;
  std::vector<SimScan> scans;
  std::vector<SimPair> pairs;  // By step, then reference index.
};

// False with *error when the options are invalid, the scene's path is too
// short for the trajectory, the ray caster fails, or a scan has no point.
bool MakeSimDataset(const SimulationOptions& options,
                    SimDataset* dataset,
                    std::string* error);

}  // namespace sim
}  // namespace mlndt
