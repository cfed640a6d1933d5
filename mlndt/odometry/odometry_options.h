#pragma once

// Everything the scan-to-local-map odometry (odometry.h) is configured by.

#include <string>

#include "mlndt/odometry/confirm_pose.h"
#include "mlndt/odometry/keyframe_policy.h"
#include "mlndt/odometry/local_map.h"
#include "mlndt/odometry/motion_prediction.h"
#include "mlndt/odometry/recovery.h"
#include "mlndt/registration/registration_options.h"

namespace mlndt {

// The registration options of the odometry's scans: the library's defaults
// (RegistrationOptions()) but three quality settings.
//  - quality_check.max_flatness = 0.8: the probe of weak directions is on
//    (the library leaves it at 0.95): a pose that can slide one cell edge
//    along a weakly constrained direction without losing inliers is
//    DEGENERATE. A wide search onto a local map of a few scans finds such
//    slides (docs/odometry.md).
//  - retry.weak_direction_rounds = 0: no search along the weak direction
//    (the library has it on); with it two steps of the Livox sequence are
//    reported CONVERGENCE 0.4-0.6 m off (docs/odometry.md).
//  - quality_check.max_mean_score = 11: LOW_QUALITY above this mean score
//    per matched point (the library leaves it off and judges the fit by the
//    median distance, because two keyframes of a narrow sensor overlap
//    little; a local map of several keyframes overlaps the scan widely, so
//    the mean counts the scan's own points, and a poor one, a slide onto a
//    shifted copy of the place, is refused).
//  - quality_check.min_localizability = 0: no localizability test (the
//    library has it on). The odometry holds a pose to its prediction (the
//    gate, the confirmation), which also holds a direction the surfaces
//    leave free; flagging those scans as well restarts the chain of
//    predictions more often (docs/odometry.md gives the measurement).
RegistrationOptions OdometryRegistrationOptions();

struct OdometryOptions {
  // The registration of each scan onto the local map. Its grid does not
  // apply (local_map.grid builds the map) and its initial_uncertainty is
  // set per scan from the prediction.
  RegistrationOptions registration = OdometryRegistrationOptions();
  LocalMapOptions local_map;
  KeyframeOptions keyframes;
  MotionPredictionOptions prediction;
  // Move each point into the frame of its scan's stamp when per-point times
  // are given (deskew.h).
  bool deskew = true;
  // A usable registration whose pose is farther from the prediction than
  // gate_factor times the prediction's uncertainty (or than the largest
  // uncertainty, prediction.max_*) is reported LOW_QUALITY. >= 1.
  double gate_factor = 3.0;
  // The search for a scan not registered from its prediction (recovery.h).
  RecoveryOptions recovery;
  // A second registration from beyond the pose for CONVERGENCE with a large
  // correction or from a prediction at its largest uncertainty
  // (confirm_pose.h); a pose it does not return to is NO_CONVERGENCE, not
  // registered. On the Livox sequence it halves the wrong poses reported
  // CONVERGENCE again (docs/odometry.md); KITTI and MulRan are unchanged.
  ConfirmationOptions confirmation;

  bool IsValid(std::string* error) const;
};

}  // namespace mlndt
