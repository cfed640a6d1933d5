#pragma once

// Constant-velocity prediction of the next scan's pose, with an uncertainty
// taken from recent motion (KISS-ICP's adaptive threshold, Vizzo et al.
// 2023, Section III-C: the model error is bounded by how much the motion
// deviated from constant velocity in recent scans).
//
// Velocity is the body-frame twist of the last relative motion divided by
// its time step; scan k is predicted at its own time stamp, so uneven scan
// rates (keyframes 0.1-0.8 s apart) extrapolate by time, not by count.

#include <deque>
#include <string>

#include "mlndt/common/types.h"

namespace mlndt {

struct MotionPredictionOptions {
  // How many recent model errors (|prediction^-1 * estimate|) the
  // uncertainty is taken from: their maximum. >= 1.
  int window = 5;
  // The uncertainty is that maximum times this factor. >= 1.
  double factor = 2.0;
  // Lower and upper bounds of the uncertainty: translation [m], rotation
  // [deg]. min >= 0, max >= min.
  double min_translation_m = 0.1;
  double max_translation_m = 2.0;
  double min_rotation_deg = 2.0;
  double max_rotation_deg = 30.0;
  // Before two poses exist (no velocity yet) the uncertainty is the
  // maximum; after k scans without a pose it is (1 + k) times the one-step
  // uncertainty (within the bounds).

  bool IsValid(std::string* error) const;
};

// How far the prediction may be from the truth.
struct PredictionUncertainty {
  double translation_m = 0.0;
  double rotation_deg = 0.0;
};

// The uncertainty of a one-step prediction from its recent model errors:
// their largest times options.factor, at least the lower bounds (not yet
// capped by the upper ones, so that a caller can scale it over a gap
// first); the upper bounds when no error is known.
PredictionUncertainty OneStepUncertainty(
    const MotionPredictionOptions& options,
    const std::deque<PredictionUncertainty>& errors);

class MotionPredictor {
 public:
  explicit MotionPredictor(const MotionPredictionOptions& options);

  // The pose at `stamp_s` (>= the last pose's stamp), extrapolated from the
  // last pose with the last velocity (after skipped scans over the time of
  // the last step at most), and its uncertainty: the largest
  // recent model error times the factor, times (1 + the scans skipped since
  // the last pose). Identity before any pose.
  Isometry3d Predict(double stamp_s) const;
  PredictionUncertainty Uncertainty() const;
  // The pose at `stamp_s` with the last velocity over the whole time since
  // the last pose (what Predict gives when no scan was skipped).
  Isometry3d DeadReckon(double stamp_s) const;

  // The body-frame twist per second (t [m/s], rotation vector [rad/s]) of
  // the last motion; zero before two poses.
  Vector6d Velocity() const { return velocity_; }

  // Adds the estimated pose of the scan at `stamp_s`. `predicted` is what
  // Predict(stamp_s) gave: its error, divided by (1 + the scans skipped
  // since the last pose), feeds the uncertainty.
  void AddPose(double stamp_s,
               const Isometry3d& predicted,
               const Isometry3d& world_from_sensor);

  // A scan whose pose is not known: the next scans are still predicted from
  // the last pose and velocity, but over one step's time at most, and the
  // uncertainty grows by one step's for each skipped scan until the next
  // AddPose.
  void SkipScan() { ++skipped_; }

  size_t num_poses() const { return num_poses_; }
  // A prediction from a known velocity has been compared with a pose.
  bool knows_model_errors() const { return !errors_.empty(); }
  // Scans skipped since the last pose.
  size_t skipped() const { return skipped_; }
  // The last pose and its stamp (identity and 0 before any).
  const Isometry3d& last_pose() const { return last_pose_; }
  double last_stamp_s() const { return last_stamp_s_; }

 private:
  MotionPredictionOptions options_;
  size_t num_poses_ = 0;
  size_t skipped_ = 0;
  double last_step_s_ = 0.0;  // Time between the last two poses.
  double last_stamp_s_ = 0.0;
  Isometry3d last_pose_ = Isometry3d::Identity();
  Vector6d velocity_ = Vector6d::Zero();
  // Model errors of recent scans: translation [m], rotation [deg].
  std::deque<PredictionUncertainty> errors_;
};

// exp and log of SE(3) in the (t, rotation vector) parametrisation used
// here: the translation and the rotation's axis-angle taken separately
// (adequate for the small motions between scans).
Vector6d MotionToTwist(const Isometry3d& motion);
Isometry3d TwistToMotion(const Vector6d& twist);

}  // namespace mlndt
