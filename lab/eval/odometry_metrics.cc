#include "lab/eval/odometry_metrics.h"

#include <algorithm>

namespace mlndt {

bool ComputeOdometryMetrics(const std::vector<Isometry3d>& reference,
                            const std::vector<OdometryResult>& results,
                            int rpe_delta,
                            const std::vector<double>& lengths_m,
                            OdometryMetrics* metrics,
                            std::string* error) {
  if (results.empty() || reference.size() < results.size()) {
    *error = "the reference has " + std::to_string(reference.size()) +
             " pose(s) for " + std::to_string(results.size()) +
             " scan(s): it needs one per scan";
    return false;
  }
  std::vector<Isometry3d> truth(reference.begin(),
                                reference.begin() + results.size());
  std::vector<Isometry3d> estimate;
  for (const OdometryResult& r : results) {
    estimate.push_back(r.world_from_sensor);
  }
  // Both start at the first scan (the odometry's frame).
  const Isometry3d first_inverse = truth.front().inverse();
  for (Isometry3d& pose : truth) pose = first_inverse * pose;
  metrics->rpe_delta_asked = rpe_delta;
  KittiSegmentOptions segments;
  segments.lengths_m = lengths_m;
  segments.first_frame_step = 1;
  RpeOptions rpe;
  rpe.delta = std::min<int>(rpe_delta, static_cast<int>(truth.size()) - 1);
  metrics->rpe_delta = rpe.delta;
  return ComputeAte(AteOptions(), truth, estimate, &metrics->ate, error) &&
         ComputeRpe(rpe, truth, estimate, &metrics->rpe, error) &&
         ComputeKittiSegmentErrors(
             segments, truth, estimate, &metrics->segments, error);
}

}  // namespace mlndt
