#pragma once

// The pair experiment behind mlndt_pairs: every scan i + gap registered
// onto scan i of a sequence with ground truth, from the identity or from
// the truth pushed off by given offsets, scored against the truth.

#include <functional>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

struct GapPairsOptions {
  std::vector<size_t> gaps = {1};        // Frames between the two scans, >= 1.
  std::vector<Vector6d> perturbations;   // Empty: start from the identity.
  double max_translation_error_m = 0.2;  // Success thresholds.
  double max_rotation_error_deg = 1.0;
};

// One registration of the experiment.
struct GapPairRun {
  size_t reference = 0;  // i.
  size_t input = 0;      // j = i + gap.
  size_t gap = 0;
  std::string start;  // "identity" or "gt+(tx,ty,tz,a,b,g)" [m, deg].
  double translation_error_m = 0.0;
  double rotation_error_deg = 0.0;
  bool success = false;  // Usable and within both thresholds.
  TerminationType termination = TerminationType::FAILURE;
  int iterations = 0;
  double time_ms = 0.0;
};

// Registers every pair (gaps in order, then i, then perturbation) and calls
// `on_run` with each; `world_from_scan` holds at least one pose per scan.
void RunGapPairs(const GapPairsOptions& pairs,
                 const RegistrationOptions& options,
                 const std::vector<PointCloud>& scans,
                 const std::vector<Isometry3d>& world_from_scan,
                 const std::function<void(const GapPairRun&)>& on_run);

}  // namespace mlndt
