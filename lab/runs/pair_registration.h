#pragma once

// Registering one scan pair of a ScanStore on the store's map of the
// reference (built once, reused afterwards). Scoring the result against the
// ground truth (PoseError, SuccessCriterion) is in lab/eval/pose_error.h.

#include <string>

#include "lab/runs/matcher.h"
#include "lab/runs/scan_store.h"
#include "mlndt/common/types.h"

namespace mlndt {

// Wall times of one pair [ms]. total = map + the registration's own total
// (sampling + solve + bookkeeping).
struct PairTimes {
  double total_ms = 0.0;
  // Building the reference map for this pair; 0 when it was reused.
  double map_ms = 0.0;
  double sampling_ms = 0.0;
  double solve_ms = 0.0;
};

// The threads the chosen method registers with (and builds its maps with).
int MatcherNumThreads(const MatcherOptions& options);

// Registers scan `input` onto scan `reference` with the chosen method, on
// the store's map of the reference (MatcherGridOptions, built with the
// method's threads). False with *error only when a scan cannot be read or
// its map cannot be built; a registration FAILURE is reported in *summary.
bool RegisterPair(const MatcherOptions& options,
                  ScanStore* store,
                  size_t reference,
                  size_t input,
                  const Isometry3d& initial_reference_from_input,
                  RegistrationSummary* summary,
                  PairTimes* times,
                  std::string* error);

}  // namespace mlndt
