#pragma once

// Writing a simulated data set in the shared data sets' format
// (shared/data/README.md), so mlndt_suite scores it unchanged:
//
//   DIR/pcd/000000.pcd ...   the scans, by index (scan_pcd.h)
//   DIR/poses.txt            KITTI format, world_from_sensor at each stamp,
//                            17 significant digits (exact round trip)
//   DIR/times.txt            each scan's stamp [s], one per line
//   DIR/reference_pairs.json per pair "i_j": the exact reference_from_input
//                            (12 numbers, row-major 3x4, p_i = T p_j),
//                            prior_from_input the same, spread_m and
//                            spread_deg 0, "source": "exact: simulated", and
//                            "free_directions" (reference_pairs.h)
//   DIR/simulation.json      sensor, scene, trajectory, seed, split and the
//                            options and random parameters; per scan its
//                            stamp and counts; per pair its constraints
//
// Every file is a function of the data set: the same seed gives the same
// bytes (no times of day, no run times).

#include <string>

#include "lab/sim/sim_dataset.h"

namespace mlndt {
namespace sim {

std::string ReferencePairsJson(const SimDataset& dataset);
std::string SimulationJson(const SimDataset& dataset);

// Writes into `dir`, created when missing. A `dir` that exists must be
// empty or hold an earlier simulation.json (an earlier simulated set, whose
// pcd/*.pcd files are replaced); anything else is refused, untouched.
// False with *error.
bool WriteSimDataset(const SimDataset& dataset,
                     const std::string& dir,
                     std::string* error);

}  // namespace sim
}  // namespace mlndt
