#include "lab/runs/pair_registration.h"

#include <glog/logging.h>

namespace mlndt {

int MatcherNumThreads(const MatcherOptions& options) {
  return options.method == Method::NDT ? options.ndt.num_threads
                                       : options.mlndt.num_threads;
}

bool RegisterPair(const MatcherOptions& options,
                  ScanStore* store,
                  size_t reference,
                  size_t input,
                  const Isometry3d& initial_reference_from_input,
                  RegistrationSummary* summary,
                  PairTimes* times,
                  std::string* error) {
  CHECK(store != nullptr);
  CHECK(summary != nullptr);
  CHECK(times != nullptr);
  CHECK(error != nullptr);
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
  const LayeredGrid* map = store->Map(reference,
                                      grid_options,
                                      MatcherNumThreads(options),
                                      &build_time_s,
                                      error);
  if (map == nullptr) return false;
  RegisterWithMatcher(
      options, *map, *input_cloud, initial_reference_from_input, summary);
  times->map_ms = build_time_s * 1e3;
  times->total_ms = (build_time_s + summary->total_time_s) * 1e3;
  times->sampling_ms = summary->sampling_time_s * 1e3;
  times->solve_ms = summary->solve_time_s * 1e3;
  return true;
}

}  // namespace mlndt
