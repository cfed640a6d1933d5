#pragma once

// A short synthetic scan sequence written to disk, for the pipeline tests:
// scan k is a fresh sampling of the street scene (synthetic_scene.h) seen
// from world_from_scan_k = (step motion)^k.

#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {
namespace testing {

struct SyntheticSequence {
  std::vector<std::string> paths;           // One .pcd per scan, in order.
  std::vector<Isometry3d> world_from_scan;  // Scan 0 is the world.
};

// Writes `num_scans` scans of `points_per_scan` points into a new folder
// under the test temp dir named `name`; each step moves the sensor by
// `step_motion` (scan_k_from_scan_k+1).
SyntheticSequence WriteSyntheticSequence(const std::string& name,
                                         int num_scans,
                                         int points_per_scan,
                                         const Isometry3d& step_motion);

// A small motion between consecutive scans: 0.4 m forward, 0.1 m left and
// 2 deg of yaw.
Isometry3d SmallStepMotion();

}  // namespace testing
}  // namespace mlndt
