#include "mlndt/odometry/recovery.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

Isometry3d TurnedAboutZ(const Isometry3d& pose, double deg) {
  Isometry3d turned = pose;
  turned.linear() = pose.linear() *
                    Eigen::AngleAxisd(deg / kRadToDeg, Eigen::Vector3d::UnitZ())
                        .toRotationMatrix();
  return turned;
}

}  // namespace

bool RecoveryOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_GE(max_search_starts, 0);
  MLNDT_OPTION_LE(max_search_starts, 5);
  MLNDT_OPTION_GT(yaw_step_deg, 0.0);
  MLNDT_OPTION_LE(yaw_step_deg, 180.0);
  return true;
}

std::vector<Isometry3d> SearchStarts(const RecoveryOptions& options,
                                     const Isometry3d& predicted,
                                     const Isometry3d& last_pose) {
  const double step = options.yaw_step_deg;
  std::vector<Isometry3d> starts = {last_pose,
                                    TurnedAboutZ(predicted, step),
                                    TurnedAboutZ(predicted, -step),
                                    TurnedAboutZ(last_pose, step),
                                    TurnedAboutZ(last_pose, -step)};
  starts.resize(static_cast<size_t>(options.max_search_starts));
  return starts;
}

Isometry3d InterpolatePose(const Isometry3d& before,
                           double before_s,
                           const Isometry3d& after,
                           double after_s,
                           double stamp_s) {
  const double span = after_s - before_s;
  const double fraction = span > 0.0 ? (stamp_s - before_s) / span : 1.0;
  return before *
         TwistToMotion(MotionToTwist(before.inverse() * after) * fraction);
}

}  // namespace mlndt
