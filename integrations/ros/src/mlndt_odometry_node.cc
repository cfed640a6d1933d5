// mlndt_odometry_node: scan-to-local-map LiDAR odometry with ML-NDT as a
// ROS 1 node (the logic is core/odometry_node_core.h; docs/ros.md).
//
//   rosrun mlndt_ros mlndt_odometry_node points:=/velodyne_points
//          _odom_frame:=odom [_gate_factor:=3 ...]
//
// Subscribes: points (sensor_msgs/PointCloud2; per-point time fields are
//   used for deskewing as mlndt_odometry does).
// Publishes: odom (nav_msgs/Odometry, odom_frame -> the sensor, with the
//   covariance), tf odom_frame -> sensor (~publish_tf), local_map
//   (sensor_msgs/PointCloud2 of the local map's finest cell means, every
//   ~local_map_period_s of scan time), path (nav_msgs/Path of every pose,
//   with the local map) and /diagnostics (diagnostic_msgs/DiagnosticArray:
//   the verdict of every cloud).
// Parameters: mlndt_odometry's flags by name (~gate_factor,
//   ~local_map_max_keyframes, ~finest_cell_size_m, ~preset, ...), the node's
//   settings and the frames (~odom_frame, ~sensor_frame: "" = the clouds'
//   frame_id). A bad parameter stops the node at start with exit code 2.

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "integrations/ros/core/odometry_node_core.h"
#include "integrations/ros/src/ros_messages.h"
#include "integrations/ros/src/ros_parameter_source.h"

namespace mlndt {
namespace ros1 {
namespace {

constexpr char kDiagnosticName[] = "mlndt_odometry: scan verdict";

class OdometryNode {
 public:
  OdometryNode(ros::NodeHandle* node,
               const ros_core::OdometryNodeOptions& options)
      : core_(options),
        odom_(node->advertise<nav_msgs::Odometry>("odom", 100)),
        local_map_(
            node->advertise<sensor_msgs::PointCloud2>("local_map", 1, true)),
        path_(node->advertise<nav_msgs::Path>("path", 1, true)),
        diagnostics_(node->advertise<diagnostic_msgs::DiagnosticArray>(
            "/diagnostics", 100)),
        points_(node->subscribe("points",
                                static_cast<uint32_t>(options.node.queue_size),
                                &OdometryNode::OnCloud,
                                this,
                                ros::TransportHints().tcpNoDelay())) {
    path_message_.header.frame_id = options.odom_frame;
  }

  const ros::Subscriber& subscriber() const { return points_; }

 private:
  void OnCloud(const sensor_msgs::PointCloud2::ConstPtr& cloud) {
    const ros::Time stamp = cloud->header.stamp;
    const ros_core::OdometryNodeOutput output =
        core_.ProcessMessage(PointCloud2ViewOf(*cloud, stamp.toSec()));
    for (const std::string& warning : output.warnings) {
      ROS_WARN("%s", warning.c_str());
    }
    const std::string& frame = core_.options().sensor_frame.empty()
                                   ? cloud->header.frame_id
                                   : core_.options().sensor_frame;
    diagnostics_.publish(
        DiagnosticMessage(stamp, kDiagnosticName, frame, output.diagnostic));
    if (!output.has_pose) return;
    if (frame.empty()) {
      ROS_WARN_ONCE("clouds without header.frame_id: set ~sensor_frame");
    }
    Publish(stamp, frame, output);
  }

  void Publish(const ros::Time& stamp,
               const std::string& frame,
               const ros_core::OdometryNodeOutput& output) {
    const std::string& odom_frame = core_.options().odom_frame;
    const Isometry3d& odom_from_sensor = output.report.pose;
    odom_.publish(OdometryMessage(
        stamp, odom_frame, frame, odom_from_sensor, output.covariance));
    if (core_.options().node.publish_tf && !frame.empty()) {
      broadcaster_.sendTransform(
          TransformMessage(stamp, odom_frame, frame, odom_from_sensor));
    }
    geometry_msgs::PoseStamped pose;
    pose.header.stamp = stamp;
    pose.header.frame_id = odom_frame;
    pose.pose = PoseMessage(odom_from_sensor);
    path_message_.poses.push_back(pose);
    if (!output.local_map_due) return;
    local_map_.publish(
        PointsMessage(stamp, odom_frame, output.local_map_points));
    path_message_.header.stamp = stamp;
    path_.publish(path_message_);
  }

  ros_core::OdometryNodeCore core_;
  ros::Publisher odom_;
  ros::Publisher local_map_;
  ros::Publisher path_;
  ros::Publisher diagnostics_;
  tf2_ros::TransformBroadcaster broadcaster_;
  nav_msgs::Path path_message_;
  ros::Subscriber points_;
};

}  // namespace
}  // namespace ros1
}  // namespace mlndt

int main(int argc, char** argv) {
  ros::init(argc, argv, "mlndt_odometry");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  mlndt::ros_core::OdometryNodeOptions options;
  std::string error;
  if (!mlndt::ros_core::OdometryNodeOptionsFromParameters(
          mlndt::ros1::RosParameterSource(private_node), &options, &error)) {
    ROS_FATAL("%s", error.c_str());
    return 2;
  }
  mlndt::ros1::OdometryNode odometry(&node, options);
  ROS_INFO("mlndt_odometry_node: clouds on %s, odometry on %s (frame %s)",
           odometry.subscriber().getTopic().c_str(),
           node.resolveName("odom").c_str(),
           options.odom_frame.c_str());
  ros::spin();
  return 0;
}
