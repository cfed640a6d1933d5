#pragma once

// The core's outputs (core/) as ROS 1 messages. Every message of a scan
// carries the cloud's own header stamp (`stamp`), never one rebuilt from
// seconds, so a consumer can match them exactly.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <sensor_msgs/PointCloud2.h>

#include <array>
#include <string>
#include <vector>

#include "integrations/ros/core/diagnostic_report.h"
#include "integrations/ros/core/ros_pose.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace ros1 {

geometry_msgs::Pose PoseMessage(const Isometry3d& parent_from_child);
Isometry3d PoseOf(const geometry_msgs::Pose& pose);

nav_msgs::Odometry OdometryMessage(const ros::Time& stamp,
                                   const std::string& parent,
                                   const std::string& child,
                                   const Isometry3d& parent_from_child,
                                   const std::array<double, 36>& covariance);

geometry_msgs::PoseWithCovarianceStamped PoseWithCovarianceMessage(
    const ros::Time& stamp,
    const std::string& frame,
    const Isometry3d& frame_from_sensor,
    const std::array<double, 36>& covariance);

geometry_msgs::TransformStamped TransformMessage(
    const ros::Time& stamp,
    const std::string& parent,
    const std::string& child,
    const Isometry3d& parent_from_child);

// float32 x, y, z, one row.
sensor_msgs::PointCloud2 PointsMessage(
    const ros::Time& stamp,
    const std::string& frame,
    const std::vector<Eigen::Vector3d>& points);

// One status named `name` (its hardware_id: the sensor frame).
diagnostic_msgs::DiagnosticArray DiagnosticMessage(
    const ros::Time& stamp,
    const std::string& name,
    const std::string& hardware_id,
    const ros_core::DiagnosticReport& report);

}  // namespace ros1
}  // namespace mlndt
