#pragma once

// The verdict of one scan as a diagnostic (diagnostic_msgs/DiagnosticStatus
// without the middleware's types): a level, a one-line message and
// key/value pairs.
//
// Levels: OK for CONVERGENCE; WARN for a pose that stands but is not
// confirmed (NO_CONVERGENCE) or for a scan whose registration is not used
// (LOW_QUALITY, DEGENERATE: the prediction stands in, the localiser keeps
// map -> odom); ERROR for FAILURE and for a message the node could not use
// (malformed, empty, a stamp not after the last).

#include <string>
#include <utility>
#include <vector>

#include "integrations/ros/core/scan_report.h"

namespace mlndt {
namespace ros_core {

enum class DiagnosticLevel { OK = 0, WARN = 1, ERROR = 2 };

struct DiagnosticReport {
  DiagnosticLevel level = DiagnosticLevel::OK;
  std::string message;
  std::vector<std::pair<std::string, std::string>> values;
};

// The diagnostic of a processed scan; `odometry` adds the odometry's fields
// (fallback, keyframe, deskewed, prediction uncertainty, map keyframes).
DiagnosticReport ScanDiagnostic(const ScanReport& report, bool odometry);
// The diagnostic of a message the node did not process, and why.
DiagnosticReport RefusedDiagnostic(double stamp_s, const std::string& reason);

}  // namespace ros_core
}  // namespace mlndt
