#pragma once

// Registering one scan pair from a ScanStore. Scoring the result against the
// ground truth (PoseError, SuccessCriterion) and the summary statistics the
// evaluation tools print (Stats) are in mlndt/eval/.

#include <string>

#include "mlndt/common/pose.h"
#include "mlndt/eval/pose_error.h"
#include "mlndt/eval/statistics.h"
#include "mlndt/registration/registration.h"
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

// Registers scan `input` onto scan `reference`. ML-NDT runs on the store's
// map of the reference (built once, reused afterwards); conventional NDT
// builds its own single grid from the reference cloud every time (the
// library has no prebuilt-grid entry point for it) and that build is the
// map time. False with *error only when a scan cannot be read or its map
// cannot be built; a registration FAILURE is reported in *summary.
inline bool RegisterPair(const RegistrationOptions& options,
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
  if (options.method == Method::NDT) {
    const PointCloud* reference_cloud = store->Cloud(reference, error);
    if (reference_cloud == nullptr) return false;
    Register(options,
             *reference_cloud,
             *input_cloud,
             initial_reference_from_input,
             summary);
    times->map_ms = summary->map_time_s * 1e3;
    times->total_ms = summary->total_time_s * 1e3;
  } else {
    double build_time_s = 0.0;
    const LayeredGrid* map =
        store->Map(reference, options.grid, &build_time_s, error);
    if (map == nullptr) return false;
    Register(
        options, *map, *input_cloud, initial_reference_from_input, summary);
    times->map_ms = build_time_s * 1e3;
    times->total_ms = (build_time_s + summary->total_time_s) * 1e3;
  }
  times->sampling_ms = summary->sampling_time_s * 1e3;
  times->solve_ms = summary->solve_time_s * 1e3;
  return true;
}

}  // namespace tools
}  // namespace mlndt
