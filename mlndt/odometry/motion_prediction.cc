#include "mlndt/odometry/motion_prediction.h"

#include <algorithm>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/pose.h"

namespace mlndt {

bool MotionPredictionOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(window, 1);
  MLNDT_OPTION_GE(factor, 1.0);
  MLNDT_OPTION_GE(min_translation_m, 0.0);
  MLNDT_OPTION_GE(max_translation_m, min_translation_m);
  MLNDT_OPTION_GE(min_rotation_deg, 0.0);
  MLNDT_OPTION_GE(max_rotation_deg, min_rotation_deg);
  MLNDT_OPTION_LE(max_rotation_deg, 180.0);
  return true;
}

Vector6d MotionToTwist(const Isometry3d& motion) {
  Vector6d twist;
  twist.head<3>() = motion.translation();
  const Eigen::AngleAxisd angle_axis(motion.linear());
  twist.tail<3>() = angle_axis.angle() * angle_axis.axis();
  return twist;
}

Isometry3d TwistToMotion(const Vector6d& twist) {
  Isometry3d motion = Isometry3d::Identity();
  const Eigen::Vector3d w = twist.tail<3>();
  const double angle = w.norm();
  if (angle > 0) {
    motion.linear() = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
  }
  motion.translation() = twist.head<3>();
  return motion;
}

MotionPredictor::MotionPredictor(const MotionPredictionOptions& options)
    : options_(options) {}

Isometry3d MotionPredictor::Predict(double stamp_s) const {
  if (num_poses_ == 0) return Isometry3d::Identity();
  double dt = std::max(0.0, stamp_s - last_stamp_s_);
  // Across skipped scans, one step's motion at most: dead reckoning through
  // a gap carries the prediction away from the map (a hand-held sensor's
  // turns and steps reverse).
  if (skipped_ > 0) dt = std::min(dt, last_step_s_);
  return last_pose_ * TwistToMotion(velocity_ * dt);
}

Isometry3d MotionPredictor::DeadReckon(double stamp_s) const {
  if (num_poses_ == 0) return Isometry3d::Identity();
  const double dt = std::max(0.0, stamp_s - last_stamp_s_);
  return last_pose_ * TwistToMotion(velocity_ * dt);
}

PredictionUncertainty OneStepUncertainty(
    const MotionPredictionOptions& options,
    const std::deque<PredictionUncertainty>& errors) {
  if (errors.empty()) {
    return {options.max_translation_m, options.max_rotation_deg};
  }
  double t = 0.0, r = 0.0;
  for (const PredictionUncertainty& e : errors) {
    t = std::max(t, e.translation_m);
    r = std::max(r, e.rotation_deg);
  }
  return {std::max(t * options.factor, options.min_translation_m),
          std::max(r * options.factor, options.min_rotation_deg)};
}

PredictionUncertainty MotionPredictor::Uncertainty() const {
  PredictionUncertainty u{options_.max_translation_m,
                          options_.max_rotation_deg};
  if (num_poses_ < 2 || errors_.empty()) return u;
  // One step's uncertainty, times the steps since the last pose, within
  // the bounds times those steps.
  const PredictionUncertainty step = OneStepUncertainty(options_, errors_);
  const double gap = 1.0 + static_cast<double>(skipped_);
  u.translation_m =
      std::min(step.translation_m * gap, options_.max_translation_m);
  u.rotation_deg = std::min(step.rotation_deg * gap, options_.max_rotation_deg);
  return u;
}

void MotionPredictor::AddPose(double stamp_s,
                              const Isometry3d& predicted,
                              const Isometry3d& world_from_sensor) {
  if (num_poses_ > 0) {
    const double dt = stamp_s - last_stamp_s_;
    if (dt > 0) {
      velocity_ = MotionToTwist(last_pose_.inverse() * world_from_sensor) / dt;
      last_step_s_ = dt;
    }
    if (num_poses_ > 1) {
      const double gap = 1.0 + static_cast<double>(skipped_);
      errors_.push_back(
          {TranslationErrorM(predicted, world_from_sensor) / gap,
           RotationErrorRad(predicted, world_from_sensor) * kRadToDeg / gap});
      while (errors_.size() > static_cast<size_t>(options_.window)) {
        errors_.pop_front();
      }
    }
  }
  last_pose_ = world_from_sensor;
  last_stamp_s_ = stamp_s;
  skipped_ = 0;
  ++num_poses_;
}

}  // namespace mlndt
