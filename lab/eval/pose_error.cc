#include "lab/eval/pose_error.h"

#include <Eigen/Geometry>

namespace mlndt {

PoseError ComputePoseError(const Isometry3d& truth,
                           const Isometry3d& estimate) {
  PoseError e;
  const Isometry3d error = truth.inverse() * estimate;
  e.components = IsometryToPoseVector(error);
  e.translation_m = error.translation().norm();
  e.rotation_rad = Eigen::AngleAxisd(error.linear()).angle();
  return e;
}

bool SuccessCriterion::IsWithin(const PoseError& error) const {
  return error.translation_m < max_translation_m &&
         error.rotation_rad * kRadToDeg < max_rotation_deg;
}

Isometry3d ScaleMotion(const Isometry3d& motion, double c) {
  const Eigen::AngleAxisd rotation(motion.linear());
  Isometry3d scaled = Isometry3d::Identity();
  scaled.linear() = Eigen::AngleAxisd(c * rotation.angle(), rotation.axis())
                        .toRotationMatrix();
  scaled.translation() = c * motion.translation();
  return scaled;
}

}  // namespace mlndt
