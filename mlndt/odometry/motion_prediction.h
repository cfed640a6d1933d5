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
  // Before two poses exist (no velocity yet), and after a scan whose pose
  // was not found, the uncertainty is the maximum.

  bool IsValid(std::string* error) const;
};

// How far the prediction may be from the truth.
struct PredictionUncertainty {
  double translation_m = 0.0;
  double rotation_deg = 0.0;
};

class MotionPredictor {
 public:
  explicit MotionPredictor(const MotionPredictionOptions& options);

  // The pose at `stamp_s` (>= the last pose's stamp) and its uncertainty.
  // Identity before any pose.
  Isometry3d Predict(double stamp_s) const;
  PredictionUncertainty Uncertainty() const;

  // The body-frame twist per second (t [m/s], rotation vector [rad/s]) of
  // the last motion; zero before two poses.
  Vector6d Velocity() const { return velocity_; }

  // Adds the estimated pose of the scan at `stamp_s`. `predicted` is what
  // Predict(stamp_s) gave (its error feeds the uncertainty).
  void AddPose(double stamp_s,
               const Isometry3d& predicted,
               const Isometry3d& world_from_sensor);

  // Adds a scan whose pose is not known (its prediction stood in for it):
  // the next scans are predicted at this pose (velocity zero: dead
  // reckoning through a run of lost scans would carry the sensor away from
  // its map), with the maximum uncertainty until the next AddPose.
  void AddPrediction(double stamp_s, const Isometry3d& predicted);

  size_t num_poses() const { return num_poses_; }

 private:
  MotionPredictionOptions options_;
  size_t num_poses_ = 0;
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
