#pragma once

// Confirmation of a scan's registration from beyond its pose: CONVERGENCE
// only for a pose the registration returns to.
//
// A registration that slides along a direction the map barely constrains
// stops where the slide ran out of pull, not at a minimum: started again
// farther along the same correction, it stays there or slides on. A pose at
// a minimum pulls the second run back. So a scan whose correction (the
// prediction -> pose motion) is large against the prediction's uncertainty,
// or whose prediction is at its largest uncertainty (no velocity known, as
// after a start or a fallback), is registered a second time from its pose
// moved on along the correction by the prediction's uncertainty (each of
// translation and rotation); the pose is confirmed when that run ends
// within the prediction's smallest uncertainty (MotionPredictionOptions::
// min_*) of it, whatever its own quality verdict (only a FAILURE has no
// pose): a run that ends farther away found a rival minimum
// (registration/rival_minima.h, with every distinct minimum a rival).
// Measured in docs/odometry.md.

#include <string>

#include "mlndt/common/types.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/registration/prepared_registration.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {

struct ConfirmationOptions {
  // Confirm CONVERGENCE at all (off: every CONVERGENCE stands).
  bool enabled = true;
  // A correction larger than this fraction of the prediction's uncertainty
  // (translation or rotation) needs the confirmation; 0 confirms every
  // scan. >= 0.
  double min_correction_fraction = 0.5;
  // A pose the second run returned to must also agree with the scan
  // registered onto the last registered scan alone (last_scan_check.h).
  bool check_last_scan = true;
  // A pose the second run did not return to is confirmed when the scan
  // registered onto the last registered scan alone is usable and agrees
  // with it (two maps, one of them a single view, find the same pose).
  bool last_scan_confirms = true;

  bool IsValid(std::string* error) const;
};

// What the second run found.
struct Confirmation {
  bool ran = false;       // The scan needed it.
  bool confirmed = true;  // It ran and returned to the pose (or not run).
  // It ran, had a pose to compare (a usable registration) and agreed.
  bool agreed = false;
  double distance_m = 0.0;  // Of the second run's pose from the first.
  double distance_deg = 0.0;
  double time_s = 0.0;  // Of the second run.
  std::string message;  // Why not confirmed.
};

// Whether the registration from `predicted` (with `uncertainty`) to `pose`
// needs the confirmation.
bool NeedsConfirmation(const ConfirmationOptions& options,
                       const MotionPredictionOptions& prediction,
                       const PredictionUncertainty& uncertainty,
                       const Isometry3d& predicted,
                       const Isometry3d& pose);

// The start of the second run: `pose` moved on along the correction
// predicted -> pose until the move is the uncertainty (each part that moved
// at all; a part that moved more keeps its length).
Isometry3d ConfirmationStart(const PredictionUncertainty& uncertainty,
                             const Isometry3d& predicted,
                             const Isometry3d& pose);

// Runs the second registration of the scan onto `map` with `scan`
// (prepared_registration.h: the scan's samples and options, whose initial
// uncertainty is the prediction's) and compares it with `pose`.
Confirmation ConfirmPose(const MotionPredictionOptions& prediction,
                         const LayeredGrid& map,
                         PreparedRegistration* scan,
                         const PredictionUncertainty& uncertainty,
                         const Isometry3d& predicted,
                         const Isometry3d& pose);

}  // namespace mlndt
