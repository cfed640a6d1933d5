#pragma once

// The odometry node without the middleware: takes the clouds as they come
// (a PointCloud2 message's view, or a scan already decoded) and says what to
// publish. A ROS 1 node (src/mlndt_odometry_node.cc) or a ROS 2 node wraps
// it: subscribe, call ProcessMessage, publish the output, log its warnings.
//
// Per cloud: DecodePointCloud2 (the decoder of mlndt_odometry --bag, so a
// bag played to the node gives the tool's points and per-point times),
// then Odometry::Process (mlndt/odometry/odometry.h; deskewed when the
// cloud has a time field), as mlndt_odometry does scan by scan: on the same
// clouds the poses are the tool's, bit for bit. A cloud the odometry cannot
// use (malformed, no finite point, a stamp not after the last one used) is
// refused with a warning and an ERROR diagnostic, and the odometry goes on
// with the next; a gap in the stamps (StampCheck) is warned about and
// bridged by the prediction.

#include <array>
#include <string>
#include <vector>

#include "integrations/ros/core/diagnostic_report.h"
#include "integrations/ros/core/odometry_parameters.h"
#include "integrations/ros/core/scan_report.h"
#include "integrations/ros/core/stamp_check.h"
#include "lab/io/point_cloud2.h"
#include "mlndt/odometry/odometry.h"

namespace mlndt {
namespace ros_core {

struct OdometryNodeOutput {
  double stamp_s = 0.0;
  std::string frame_id;  // The cloud's header.frame_id.
  // The scan got a pose (registered, or its prediction on a fallback):
  // publish odom_from_sensor = report.pose with `covariance`, and the
  // transform. False: the cloud was refused; publish only the diagnostic.
  bool has_pose = false;
  ScanReport report;
  std::array<double, 36> covariance{};  // ros_pose.h's order.
  DiagnosticReport diagnostic;
  // To log as warnings (refusals, gaps, fallbacks, map restarts).
  std::vector<std::string> warnings;
  // The local map is due (OdometryNodeSettings::local_map_period_s): its
  // finest cell means in the odom frame (map_points.h).
  bool local_map_due = false;
  std::vector<Eigen::Vector3d> local_map_points;
};

class OdometryNodeCore {
 public:
  // `options` as OdometryNodeOptionsFromParameters makes them (valid).
  explicit OdometryNodeCore(const OdometryNodeOptions& options);

  OdometryNodeOutput ProcessMessage(const PointCloud2View& message);
  OdometryNodeOutput Process(const PointCloud2Scan& scan);

  const OdometryNodeOptions& options() const { return options_; }
  // Clouds that got a pose.
  size_t num_used() const { return num_used_; }

 private:
  OdometryNodeOutput Refuse(double stamp_s,
                            const std::string& frame_id,
                            const std::string& reason) const;
  void AddLocalMap(OdometryNodeOutput* output);

  OdometryNodeOptions options_;
  Odometry odometry_;
  StampCheck stamps_;
  size_t num_used_ = 0;
  bool local_map_published_ = false;
  double local_map_stamp_s_ = 0.0;
};

}  // namespace ros_core
}  // namespace mlndt
