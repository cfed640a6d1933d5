// mlndt_localizer_node: localisation in a map built by mlndt_map as a ROS 1
// node (the logic is core/localizer_node_core.h; docs/ros.md).
//
//   rosrun mlndt_ros mlndt_localizer_node points:=/velodyne_points
//          _map:=map.mlndt [_initial_guess:=tx,ty,tz,a,b,g]
//
// Subscribes: points (sensor_msgs/PointCloud2), initialpose
//   (geometry_msgs/PoseWithCovarianceStamped in ~map_frame: RViz's "2D Pose
//   Estimate"; each one restarts the localisation from it).
// Publishes: pose (geometry_msgs/PoseWithCovarianceStamped, map_from_sensor
//   with the covariance, for usable results only), tf map_frame ->
//   odom_frame (with odom_frame -> sensor from an odometry on tf at the
//   cloud's stamp) or, with ~odom_frame empty, map_frame -> sensor;
//   map_cloud (latched, the map's finest cell means) and /diagnostics (the
//   verdict of every cloud). A LOW_QUALITY, DEGENERATE or FAILURE result
//   moves nothing: a ROS warning and the diagnostic say so.
// Parameters: mlndt_localize's flags by name (~map, ~initial_guess,
//   ~motion_model, ~preset, ~initial_uncertainty and the registration's but
//   the map's), the node's settings and the frames. A bad parameter or map
//   stops the node at start with exit code 2.

#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <memory>

#include "integrations/ros/core/localizer_node_core.h"
#include "integrations/ros/core/map_points.h"
#include "integrations/ros/src/ros_messages.h"
#include "integrations/ros/src/ros_parameter_source.h"

namespace mlndt {
namespace ros1 {
namespace {

constexpr char kDiagnosticName[] = "mlndt_localizer: scan verdict";

class LocalizerNode {
 public:
  LocalizerNode(ros::NodeHandle* node,
                std::unique_ptr<ros_core::LocalizerNodeCore> core)
      : core_(std::move(core)),
        options_(core_->options()),
        listener_(buffer_),
        pose_(node->advertise<geometry_msgs::PoseWithCovarianceStamped>("pose",
                                                                        100)),
        map_cloud_(
            node->advertise<sensor_msgs::PointCloud2>("map_cloud", 1, true)),
        diagnostics_(node->advertise<diagnostic_msgs::DiagnosticArray>(
            "/diagnostics", 100)),
        initial_pose_(node->subscribe(
            "initialpose", 1, &LocalizerNode::OnInitialPose, this)),
        points_(node->subscribe("points",
                                static_cast<uint32_t>(options_.node.queue_size),
                                &LocalizerNode::OnCloud,
                                this,
                                ros::TransportHints().tcpNoDelay())) {
    map_cloud_.publish(PointsMessage(ros::Time::now(),
                                     options_.map_frame,
                                     ros_core::FinestCellMeans(core_->map())));
  }

  const ros::Subscriber& subscriber() const { return points_; }

 private:
  void OnInitialPose(
      const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& pose) {
    const std::string& frame = pose->header.frame_id;
    if (!frame.empty() && frame != options_.map_frame) {
      ROS_WARN("initial pose in frame '%s' ignored: give it in ~map_frame '%s'",
               frame.c_str(),
               options_.map_frame.c_str());
      return;
    }
    core_->SetInitialPose(PoseOf(pose->pose.pose));
    ROS_INFO("localising from the initial pose (%.3f, %.3f, %.3f)",
             pose->pose.pose.position.x,
             pose->pose.pose.position.y,
             pose->pose.pose.position.z);
  }

  // odom -> sensor at `stamp` from the odometry on tf, when there is one.
  ros_core::OdomPose LookUpOdom(const ros::Time& stamp,
                                const std::string& sensor_frame) {
    ros_core::OdomPose odom;
    if (!core_->with_odometry()) return odom;
    try {
      const geometry_msgs::TransformStamped t =
          buffer_.lookupTransform(options_.odom_frame,
                                  sensor_frame,
                                  stamp,
                                  ros::Duration(options_.node.tf_timeout_s));
      geometry_msgs::Pose pose;
      pose.position.x = t.transform.translation.x;
      pose.position.y = t.transform.translation.y;
      pose.position.z = t.transform.translation.z;
      pose.orientation = t.transform.rotation;
      odom.available = true;
      odom.odom_from_sensor = PoseOf(pose);
    } catch (const tf2::TransformException& e) {
      ROS_DEBUG("odom -> sensor: %s", e.what());
    }
    return odom;
  }

  void OnCloud(const sensor_msgs::PointCloud2::ConstPtr& cloud) {
    const ros::Time stamp = cloud->header.stamp;
    const std::string& frame = options_.sensor_frame.empty()
                                   ? cloud->header.frame_id
                                   : options_.sensor_frame;
    if (!core_->has_initial_pose()) {
      ROS_WARN_THROTTLE(5.0,
                        "waiting for an initial pose on %s (RViz's 2D Pose "
                        "Estimate) or ~initial_guess",
                        initial_pose_.getTopic().c_str());
      return;
    }
    const ros_core::LocalizerNodeOutput output = core_->ProcessMessage(
        PointCloud2ViewOf(*cloud, stamp.toSec()), LookUpOdom(stamp, frame));
    for (const std::string& warning : output.warnings) {
      ROS_WARN("%s", warning.c_str());
    }
    diagnostics_.publish(
        DiagnosticMessage(stamp, kDiagnosticName, frame, output.diagnostic));
    if (output.has_pose) {
      pose_.publish(PoseWithCovarianceMessage(
          stamp, options_.map_frame, output.report.pose, output.covariance));
    }
    if (output.has_transform && options_.node.publish_tf) {
      const std::string& child =
          core_->with_odometry() ? options_.odom_frame : frame;
      broadcaster_.sendTransform(TransformMessage(
          stamp, options_.map_frame, child, output.map_from_child));
    }
  }

  std::unique_ptr<ros_core::LocalizerNodeCore> core_;
  const ros_core::LocalizerNodeOptions& options_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  tf2_ros::TransformBroadcaster broadcaster_;
  ros::Publisher pose_;
  ros::Publisher map_cloud_;
  ros::Publisher diagnostics_;
  ros::Subscriber initial_pose_;
  ros::Subscriber points_;
};

}  // namespace
}  // namespace ros1
}  // namespace mlndt

int main(int argc, char** argv) {
  ros::init(argc, argv, "mlndt_localizer");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  mlndt::ros_core::LocalizerNodeOptions options;
  std::unique_ptr<mlndt::ros_core::LocalizerNodeCore> core;
  std::string error;
  if (!mlndt::ros_core::LocalizerNodeOptionsFromParameters(
          mlndt::ros1::RosParameterSource(private_node), &options, &error) ||
      !mlndt::ros_core::LocalizerNodeCore::Create(options, &core, &error)) {
    ROS_FATAL("%s", error.c_str());
    return 2;
  }
  ROS_INFO("mlndt_localizer_node: map %s (%d layers), %s",
           options.map_path.c_str(),
           core->map().num_layers(),
           options.has_initial_pose ? "from ~initial_guess"
                                    : "waiting for an initial pose");
  mlndt::ros1::LocalizerNode localizer(&node, std::move(core));
  ros::spin();
  return 0;
}
