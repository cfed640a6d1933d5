#pragma once

// What the odometry does with a scan it could not register from its
// prediction (odometry.h): search for it from wider starts, and when it
// stays unregistered, bridge it by interpolation once a later scan is
// registered.
//
// The search registers the scan again onto the local map from starts
// around the prediction: after skipped scans the pose dead-reckoned over
// the gap (the odometry adds it), the last registered pose (the velocity
// may have changed sign, as a hand-held sensor's sweeps do), and the
// prediction and the last pose turned about the sensor's z axis by
// +-yaw_step_deg; then onto the last registered scan alone (a map of one
// view, which a sensor that walks on leaves later than the local map's
// keyframes), where the scan registered onto the local map from the pose
// found must be usable and end within the prediction's smallest
// uncertainty of it. A start's result counts only when the odometry's whole
// verdict (gate, confirmation from beyond the pose, last-scan check) calls
// it CONVERGENCE. The local map is never rebuilt around a pose that is only
// a prediction: an unregistered scan does not join it, and its pose is
// interpolated between the registered scans before and after it, by time
// stamp.

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/odometry/motion_prediction.h"

namespace mlndt {

struct RecoveryOptions {
  // Starts onto the local map tried, in the order above (besides the
  // dead-reckoned one), for a scan not registered from its prediction; 0 =
  // none (and no dead-reckoned start). In [0, 5].
  int max_search_starts = 1;
  // The turn about the sensor's z axis of the turned starts [deg]. > 0.
  double yaw_step_deg = 15.0;
  // After those, the scan registered onto the last registered scan alone
  // (a map of one view, which a sensor that walks on leaves later than the
  // local map's keyframes), from the prediction.
  bool register_onto_last_scan = true;

  bool IsValid(std::string* error) const;
};

// The search's starts for a scan predicted at `predicted`, the last
// registered pose being `last_pose`: at most options.max_search_starts.
std::vector<Isometry3d> SearchStarts(const RecoveryOptions& options,
                                     const Isometry3d& predicted,
                                     const Isometry3d& last_pose);

// The pose at `stamp_s` between `before` (at `before_s`) and `after` (at
// `after_s` > before_s): translation and rotation vector of
// before^-1 * after scaled by the fraction of the time elapsed.
Isometry3d InterpolatePose(const Isometry3d& before,
                           double before_s,
                           const Isometry3d& after,
                           double after_s,
                           double stamp_s);

}  // namespace mlndt
