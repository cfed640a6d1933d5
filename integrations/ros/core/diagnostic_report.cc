#include "integrations/ros/core/diagnostic_report.h"

#include <cstdio>

namespace mlndt {
namespace ros_core {
namespace {

std::string Number(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

std::string Flag(bool value) { return value ? "true" : "false"; }

DiagnosticLevel LevelOf(const ScanReport& report) {
  if (report.termination == TerminationType::FAILURE) {
    return DiagnosticLevel::ERROR;
  }
  if (report.termination == TerminationType::CONVERGENCE && report.registered) {
    return DiagnosticLevel::OK;
  }
  return DiagnosticLevel::WARN;
}

}  // namespace

DiagnosticReport ScanDiagnostic(const ScanReport& report, bool odometry) {
  DiagnosticReport d;
  d.level = LevelOf(report);
  d.message = TerminationTypeToString(report.termination);
  if (!report.registered) d.message += " (not used: the prediction stands in)";
  if (!report.message.empty()) d.message += ": " + report.message;
  d.values = {{"stamp_s", Number(report.stamp_s, 9)},
              {"scan", std::to_string(report.index)},
              {"termination_type", TerminationTypeToString(report.termination)},
              {"registered", Flag(report.registered)},
              {"covariance_known", Flag(report.has_covariance)},
              {"correction_m", Number(report.correction_m, 4)},
              {"correction_deg", Number(report.correction_deg, 3)},
              {"start_layer", std::to_string(report.start_layer)},
              {"iterations", std::to_string(report.iterations)},
              {"inlier_fraction", Number(report.inlier_fraction, 3)},
              {"registration_time_s", Number(report.registration_time_s, 4)}};
  if (odometry) {
    d.values.insert(
        d.values.end(),
        {{"fallback", Flag(!report.registered)},
         {"keyframe", Flag(report.keyframe)},
         {"recovered", Flag(report.recovered)},
         {"deskewed", Flag(report.deskewed)},
         {"prediction_uncertainty_m", Number(report.uncertainty_m, 3)},
         {"prediction_uncertainty_deg", Number(report.uncertainty_deg, 2)},
         {"map_keyframes", std::to_string(report.map_keyframes)}});
  }
  return d;
}

DiagnosticReport RefusedDiagnostic(double stamp_s, const std::string& reason) {
  DiagnosticReport d;
  d.level = DiagnosticLevel::ERROR;
  d.message = "scan not used: " + reason;
  d.values = {{"stamp_s", Number(stamp_s, 9)}, {"termination_type", "REFUSED"}};
  return d;
}

}  // namespace ros_core
}  // namespace mlndt
