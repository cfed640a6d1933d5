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

struct OdometryOptions {
  // The registration of each scan onto the local map. Its grid does not
  // apply (local_map.grid builds the map), its initial_uncertainty is set
  // per scan from the prediction, and its quality_check.max_flatness and
  // max_mean_score and retry.weak_direction_rounds are replaced by the
  // fields of those names below.
  RegistrationOptions registration;
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
  // The probe of weak directions for the scans' registrations
  // (QualityCheckOptions::max_flatness, which it replaces): a pose that can
  // slide one cell edge along a weakly constrained direction without losing
  // inliers is DEGENERATE. On here although
  // the library leaves it off: a wide search onto a local map of a few
  // scans finds such slides (docs/odometry.md: on the Livox sequence it
  // cuts the wrong poses reported CONVERGENCE by more than half; KITTI and
  // MulRan are unchanged). In (0, 1]; 1 = off.
  double max_flatness = 0.8;
  // The search along the weak direction for the scans' registrations
  // (RetryOptions::weak_direction_rounds, which it replaces): off here
  // although the library has it on. On the Livox sequence it takes the ATE
  // from 3.45 m to 2.38 m, but two steps are then reported CONVERGENCE
  // 0.4-0.6 m off (docs/odometry.md; 0 without it). In [0, 16]; 0 = off.
  int weak_direction_rounds = 0;
  // The mean score per matched point above which a scan's registration is
  // LOW_QUALITY (QualityCheckOptions::max_mean_score, which it replaces):
  // on here although the library leaves it off. The library judges the fit
  // by the median distance, because two keyframes of a narrow sensor overlap
  // little; a local map of several keyframes overlaps the scan widely, so
  // the mean counts the scan's own points, and a poor one (a slide onto a
  // shifted copy of the place) is refused (docs/odometry.md). In (0, 1e6];
  // 1e6 = off.
  double max_mean_score = 11.0;
  // A second registration from beyond the pose for CONVERGENCE with a large
  // correction or from a prediction at its largest uncertainty
  // (confirm_pose.h); a pose it does not return to is NO_CONVERGENCE, not
  // registered. On the Livox sequence it halves the wrong poses reported
  // CONVERGENCE again (docs/odometry.md); KITTI and MulRan are unchanged.
  ConfirmationOptions confirmation;

  bool IsValid(std::string* error) const;
};

}  // namespace mlndt
