#pragma once

// What the nodes publish about one scan, read from the library's results.
// This file is the only one of the nodes that reads OdometryResult,
// LocalizationResult and RegistrationSummary: when those structs change,
// ReportOf changes and nothing else.

#include <string>

#include "mlndt/common/types.h"
#include "mlndt/odometry/odometry.h"
#include "mlndt/pipeline/localizer.h"
#include "mlndt/registration/registration_summary.h"

namespace mlndt {
namespace ros_core {

struct ScanReport {
  size_t index = 0;  // 0-based among the scans processed.
  double stamp_s = 0.0;
  // odom_from_sensor (odometry) or map_from_sensor (localiser), and the
  // prediction it started from.
  Isometry3d pose = Isometry3d::Identity();
  Isometry3d predicted = Isometry3d::Identity();
  TerminationType termination = TerminationType::FAILURE;
  std::string message;
  // The pose came from the registration (IsUsableTermination and, for the
  // odometry, not a fallback); otherwise it is the prediction.
  bool registered = false;
  // The covariance of the pose vector xi (t [m], Euler angles [rad];
  // mlndt/common/pose.h) when known (a registration's Laplace covariance
  // or, for an odometry fallback, the prediction's uncertainty).
  bool has_covariance = false;
  Matrix6d covariance = Matrix6d::Zero();
  // Odometry only.
  bool keyframe = false;
  bool recovered = false;  // Registered from a search start.
  bool deskewed = false;
  double uncertainty_m = 0.0;  // Of the prediction.
  double uncertainty_deg = 0.0;
  size_t map_keyframes = 0;
  // Both.
  double correction_m = 0.0;  // Pose against the prediction.
  double correction_deg = 0.0;
  int start_layer = 0;
  int iterations = 0;
  double inlier_fraction = 0.0;
  double registration_time_s = 0.0;
};

ScanReport ReportOf(const OdometryResult& result);
ScanReport ReportOf(const LocalizationResult& result, double stamp_s);

}  // namespace ros_core
}  // namespace mlndt
