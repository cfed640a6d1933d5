#include "integrations/ros/core/odometry_node_core.h"

#include <cstdio>

#include "integrations/ros/core/map_points.h"
#include "integrations/ros/core/ros_pose.h"

namespace mlndt {
namespace ros_core {
namespace {

std::string At(double stamp_s) {
  char text[64];
  std::snprintf(text, sizeof(text), "scan at %.6f s: ", stamp_s);
  return text;
}

}  // namespace

OdometryNodeCore::OdometryNodeCore(const OdometryNodeOptions& options)
    : options_(options), odometry_(options.odometry) {}

OdometryNodeOutput OdometryNodeCore::ProcessMessage(
    const PointCloud2View& message) {
  PointCloud2Scan scan;
  std::string error;
  if (!DecodePointCloud2(message, &scan, &error)) {
    return Refuse(message.stamp_s, message.frame_id, "malformed: " + error);
  }
  return Process(scan);
}

OdometryNodeOutput OdometryNodeCore::Refuse(double stamp_s,
                                            const std::string& frame_id,
                                            const std::string& reason) const {
  OdometryNodeOutput output;
  output.stamp_s = stamp_s;
  output.frame_id = frame_id;
  output.diagnostic = RefusedDiagnostic(stamp_s, reason);
  output.warnings.push_back(At(stamp_s) + "not used: " + reason);
  return output;
}

OdometryNodeOutput OdometryNodeCore::Process(const PointCloud2Scan& scan) {
  if (scan.cloud.empty()) {
    return Refuse(scan.stamp_s, scan.frame_id, "no finite points");
  }
  std::string refusal, gap;
  if (!stamps_.Check(scan.stamp_s, &refusal, &gap)) {
    return Refuse(scan.stamp_s, scan.frame_id, refusal);
  }
  OdometryResult result;
  std::string error;
  if (!odometry_.Process(
          {scan.stamp_s, &scan.cloud, &scan.point_times_s}, &result, &error)) {
    return Refuse(scan.stamp_s, scan.frame_id, error);
  }
  stamps_.Use(scan.stamp_s);
  ++num_used_;

  OdometryNodeOutput output;
  output.stamp_s = scan.stamp_s;
  output.frame_id = scan.frame_id;
  output.has_pose = true;
  output.report = ReportOf(result);
  const ScanReport& report = output.report;
  output.covariance =
      ToRosCovariance(report.pose, report.covariance, report.has_covariance);
  output.diagnostic = ScanDiagnostic(report, true);
  if (!gap.empty()) output.warnings.push_back(At(scan.stamp_s) + gap);
  if (!report.registered) {
    output.warnings.push_back(At(scan.stamp_s) + output.diagnostic.message);
  }
  AddLocalMap(&output);
  return output;
}

void OdometryNodeCore::AddLocalMap(OdometryNodeOutput* output) {
  const double period = options_.node.local_map_period_s;
  if (local_map_published_ && output->stamp_s - local_map_stamp_s_ < period) {
    return;
  }
  output->local_map_due = true;
  output->local_map_points = FinestCellMeans(odometry_.local_map().grid());
  local_map_published_ = true;
  local_map_stamp_s_ = output->stamp_s;
}

}  // namespace ros_core
}  // namespace mlndt
