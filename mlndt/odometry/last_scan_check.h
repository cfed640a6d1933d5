#pragma once

// The second half of the confirmation (confirm_pose.h): a pose of the local
// map must agree with the scan registered onto the last registered scan
// alone.
//
// The local map is the union of the last keyframes at their poses. When
// some of those poses were wrong (a NO_CONVERGENCE pose is kept and may
// join the map), the map holds two copies of a place, shifted against each
// other, and a scan can settle on either: a minimum the registration
// returns to from beyond the pose, with a good fit, yet off the last
// registered pose by the shift (docs/odometry.md, "the last-scan check":
// on the Livox sequence 1.7 m). The last registered scan on its own holds
// one copy only. So the scan is registered onto it too, from the same
// prediction with the same uncertainty (the scan-to-scan registration
// mlndt_sequence runs); when that registration is usable and ends farther
// than the prediction's smallest uncertainty (MotionPredictionOptions::
// min_*) from the pose, the two maps disagree about the scan and the pose
// is not confirmed. A last-scan registration that is not usable is no
// evidence either way.

#include <string>

#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/odometry/confirm_pose.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/registration/prepared_registration.h"

namespace mlndt {

// Registers the scan onto `last_scan_map` (the map of the last registered
// scan alone, in the world frame) from `predicted` with `scan`
// (prepared_registration.h: the scan's samples and options, whose initial
// uncertainty is the prediction's) and compares the result with `pose`.
Confirmation CheckAgainstLastScan(const MotionPredictionOptions& prediction,
                                  const LayeredGrid& last_scan_map,
                                  PreparedRegistration* scan,
                                  const Isometry3d& predicted,
                                  const Isometry3d& pose);

}  // namespace mlndt
