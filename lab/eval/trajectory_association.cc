#include "lab/eval/trajectory_association.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

namespace mlndt {
namespace {

void AddPair(const Trajectory& reference,
             const Trajectory& estimate,
             size_t reference_index,
             size_t estimate_index,
             AssociatedPoses* pairs) {
  pairs->reference_indices.push_back(reference_index);
  pairs->estimate_indices.push_back(estimate_index);
  pairs->reference.push_back(reference.world_from_sensor(reference_index));
  pairs->estimate.push_back(estimate.world_from_sensor(estimate_index));
}

// Index of the timestamp in `times` (sorted, not empty) nearest to t; the
// earlier one on a tie.
size_t Nearest(const std::vector<double>& times, double t) {
  const auto after = std::lower_bound(times.begin(), times.end(), t);
  if (after == times.begin()) return 0;
  const size_t i = static_cast<size_t>(after - times.begin());
  if (after == times.end()) return i - 1;
  return t - times[i - 1] <= *after - t ? i - 1 : i;
}

}  // namespace

AssociatedPoses AssociateByIndex(const Trajectory& reference,
                                 const Trajectory& estimate) {
  AssociatedPoses pairs;
  const size_t n = std::min(reference.size(), estimate.size());
  for (size_t k = 0; k < n; ++k) AddPair(reference, estimate, k, k, &pairs);
  return pairs;
}

AssociatedPoses AssociateByTimestamp(const Trajectory& reference,
                                     const Trajectory& estimate,
                                     double max_difference_s) {
  CHECK(max_difference_s >= 0.0) << "max_difference_s " << max_difference_s;
  AssociatedPoses pairs;
  if (reference.empty()) return pairs;
  const std::vector<double>& times = reference.timestamps_s();
  // Candidates (reference index, estimate index) in estimate order; the
  // reference index never decreases because both lists are sorted.
  std::vector<std::pair<size_t, size_t>> candidates;
  for (size_t j = 0; j < estimate.size(); ++j) {
    const double t = estimate.timestamp_s(j);
    const size_t i = Nearest(times, t);
    if (std::abs(times[i] - t) > max_difference_s) continue;
    if (!candidates.empty() && candidates.back().first == i) {
      // Same reference pose as the previous estimate pose: keep the closer.
      const double previous =
          std::abs(times[i] - estimate.timestamp_s(candidates.back().second));
      if (std::abs(times[i] - t) < previous) candidates.back().second = j;
      continue;
    }
    candidates.emplace_back(i, j);
  }
  for (const auto& [i, j] : candidates)
    AddPair(reference, estimate, i, j, &pairs);
  return pairs;
}

}  // namespace mlndt
