#pragma once

// Registering one scan pair from a ScanStore. Scoring the result against the
// ground truth (PoseError, SuccessCriterion) and the summary statistics the
// evaluation tools print (Stats) are in mlndt/eval/.

#include <string>

#include "mlndt/common/pose.h"
#include "mlndt/eval/pose_error.h"
#include "mlndt/eval/statistics.h"
#include "mlndt/pipeline/matcher.h"
#include "tools/common/scan_store.h"

namespace mlndt {
namespace tools {

// Wall times of one pair [ms]. total = map + the registration's own total
// (sampling + solve + bookkeeping).
struct PairTimes {
  double total_ms = 0.0;
  double map_ms =
      0.0;  // Building the reference map for this pair; 0 when reused.
  double sampling_ms = 0.0;
  double solve_ms = 0.0;
};

// Registers scan `input` onto scan `reference` with the chosen method, on
// the store's map of the reference (built once, reused afterwards). False
// with *error only when a scan cannot be read or its map cannot be built; a
// registration FAILURE is reported in *summary.
inline bool RegisterPair(const MatcherOptions& options,
                         ScanStore* store,
                         size_t reference,
                         size_t input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary,
                         PairTimes* times,
                         std::string* error) {
  *summary = RegistrationSummary();
  *times = PairTimes();
  const PointCloud* input_cloud = store->Cloud(input, error);
  if (input_cloud == nullptr) return false;
  const PointCloud* reference_cloud = store->Cloud(reference, error);
  if (reference_cloud == nullptr) return false;
  LayeredGridOptions grid_options;
  if (!MatcherGridOptions(options, *reference_cloud, &grid_options, error)) {
    *error = store->path(reference) + ": map: " + *error;
    return false;
  }
  double build_time_s = 0.0;
  const LayeredGrid* map =
      store->Map(reference, grid_options, &build_time_s, error);
  if (map == nullptr) return false;
  RegisterWithMatcher(
      options, *map, *input_cloud, initial_reference_from_input, summary);
  times->map_ms = build_time_s * 1e3;
  times->total_ms = (build_time_s + summary->total_time_s) * 1e3;
  times->sampling_ms = summary->sampling_time_s * 1e3;
  times->solve_ms = summary->solve_time_s * 1e3;
  return true;
}

}  // namespace tools
}  // namespace mlndt
