#include "integrations/ros/core/scan_report.h"

#include "mlndt/common/pose.h"

namespace mlndt {
namespace ros_core {
namespace {

// A prediction's uncertainty as a covariance of xi: its translation and
// rotation bounds as standard deviations on each axis.
Matrix6d PredictionCovariance(double translation_m, double rotation_deg) {
  Vector6d variances;
  const double rotation_rad = rotation_deg * kDegToRad;
  variances << Eigen::Vector3d::Constant(translation_m * translation_m),
      Eigen::Vector3d::Constant(rotation_rad * rotation_rad);
  return variances.asDiagonal();
}

}  // namespace

ScanReport ReportOf(const OdometryResult& result) {
  ScanReport report;
  report.index = result.index;
  report.stamp_s = result.stamp_s;
  report.pose = result.world_from_sensor;
  report.predicted = result.predicted_world_from_sensor;
  report.termination = result.termination_type;
  report.message = result.message;
  report.registered = !result.fallback;
  // A registered pose has no covariance here yet; the registration's is
  // result.registration.covariance.
  if (result.fallback) {
    report.has_covariance = true;
    report.covariance = PredictionCovariance(result.uncertainty.translation_m,
                                             result.uncertainty.rotation_deg);
  }
  report.keyframe = result.keyframe;
  report.recovered = result.recovered;
  report.deskewed = result.deskewed;
  report.uncertainty_m = result.uncertainty.translation_m;
  report.uncertainty_deg = result.uncertainty.rotation_deg;
  report.map_keyframes = result.map_keyframes;
  report.correction_m = result.correction_m;
  report.correction_deg = result.correction_rad * kRadToDeg;
  report.start_layer = result.registration.start_layer;
  report.iterations = result.registration.num_iterations;
  report.inlier_fraction = result.registration.quality.inlier_fraction;
  report.registration_time_s = result.registration_time_s;
  return report;
}

ScanReport ReportOf(const LocalizationResult& result, double stamp_s) {
  const RegistrationSummary& summary = result.registration;
  ScanReport report;
  report.index = result.index;
  report.stamp_s = stamp_s;
  report.pose = result.map_from_scan;
  report.predicted = result.predicted_map_from_scan;
  report.termination = result.registration.termination_type;
  report.message = result.registration.message;
  report.registered = result.IsSolutionUsable();
  report.has_covariance = report.registered;
  if (report.registered) report.covariance = summary.covariance;
  report.correction_m =
      TranslationErrorM(result.map_from_scan, result.predicted_map_from_scan);
  report.correction_deg =
      RotationErrorRad(result.map_from_scan, result.predicted_map_from_scan) *
      kRadToDeg;
  report.start_layer = summary.start_layer;
  report.iterations = result.registration.num_iterations;
  report.inlier_fraction = result.registration.quality.inlier_fraction;
  report.registration_time_s = result.registration.total_time_s;
  return report;
}

}  // namespace ros_core
}  // namespace mlndt
