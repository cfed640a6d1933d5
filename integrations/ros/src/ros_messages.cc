#include "integrations/ros/src/ros_messages.h"

#include <cstring>

namespace mlndt {
namespace ros1 {

geometry_msgs::Pose PoseMessage(const Isometry3d& parent_from_child) {
  const ros_core::RosPose pose = ros_core::ToRosPose(parent_from_child);
  geometry_msgs::Pose message;
  message.position.x = pose.position.x();
  message.position.y = pose.position.y();
  message.position.z = pose.position.z();
  message.orientation.x = pose.orientation.x();
  message.orientation.y = pose.orientation.y();
  message.orientation.z = pose.orientation.z();
  message.orientation.w = pose.orientation.w();
  return message;
}

Isometry3d PoseOf(const geometry_msgs::Pose& pose) {
  ros_core::RosPose p;
  p.position = {pose.position.x, pose.position.y, pose.position.z};
  p.orientation = Eigen::Quaterniond(pose.orientation.w,
                                     pose.orientation.x,
                                     pose.orientation.y,
                                     pose.orientation.z);
  return ros_core::FromRosPose(p);
}

nav_msgs::Odometry OdometryMessage(const ros::Time& stamp,
                                   const std::string& parent,
                                   const std::string& child,
                                   const Isometry3d& parent_from_child,
                                   const std::array<double, 36>& covariance) {
  nav_msgs::Odometry message;
  message.header.stamp = stamp;
  message.header.frame_id = parent;
  message.child_frame_id = child;
  message.pose.pose = PoseMessage(parent_from_child);
  for (size_t i = 0; i < 36; ++i) message.pose.covariance[i] = covariance[i];
  // The twist is not estimated: its covariance says so.
  message.twist.covariance[0] = -1.0;
  return message;
}

geometry_msgs::PoseWithCovarianceStamped PoseWithCovarianceMessage(
    const ros::Time& stamp,
    const std::string& frame,
    const Isometry3d& frame_from_sensor,
    const std::array<double, 36>& covariance) {
  geometry_msgs::PoseWithCovarianceStamped message;
  message.header.stamp = stamp;
  message.header.frame_id = frame;
  message.pose.pose = PoseMessage(frame_from_sensor);
  for (size_t i = 0; i < 36; ++i) message.pose.covariance[i] = covariance[i];
  return message;
}

geometry_msgs::TransformStamped TransformMessage(
    const ros::Time& stamp,
    const std::string& parent,
    const std::string& child,
    const Isometry3d& parent_from_child) {
  const geometry_msgs::Pose pose = PoseMessage(parent_from_child);
  geometry_msgs::TransformStamped message;
  message.header.stamp = stamp;
  message.header.frame_id = parent;
  message.child_frame_id = child;
  message.transform.translation.x = pose.position.x;
  message.transform.translation.y = pose.position.y;
  message.transform.translation.z = pose.position.z;
  message.transform.rotation = pose.orientation;
  return message;
}

sensor_msgs::PointCloud2 PointsMessage(
    const ros::Time& stamp,
    const std::string& frame,
    const std::vector<Eigen::Vector3d>& points) {
  sensor_msgs::PointCloud2 message;
  message.header.stamp = stamp;
  message.header.frame_id = frame;
  message.height = 1;
  message.width = static_cast<uint32_t>(points.size());
  const char* names[] = {"x", "y", "z"};
  for (uint32_t k = 0; k < 3; ++k) {
    sensor_msgs::PointField field;
    field.name = names[k];
    field.offset = 4 * k;
    field.datatype = sensor_msgs::PointField::FLOAT32;
    field.count = 1;
    message.fields.push_back(field);
  }
  message.is_bigendian = false;
  message.point_step = 12;
  message.row_step = message.point_step * message.width;
  message.is_dense = true;
  message.data.resize(message.row_step);
  for (size_t i = 0; i < points.size(); ++i) {
    const float xyz[3] = {static_cast<float>(points[i].x()),
                          static_cast<float>(points[i].y()),
                          static_cast<float>(points[i].z())};
    std::memcpy(message.data.data() + 12 * i, xyz, 12);
  }
  return message;
}

diagnostic_msgs::DiagnosticArray DiagnosticMessage(
    const ros::Time& stamp,
    const std::string& name,
    const std::string& hardware_id,
    const ros_core::DiagnosticReport& report) {
  diagnostic_msgs::DiagnosticStatus status;
  status.level = static_cast<uint8_t>(report.level);
  status.name = name;
  status.hardware_id = hardware_id;
  status.message = report.message;
  for (const auto& [key, value] : report.values) {
    diagnostic_msgs::KeyValue pair;
    pair.key = key;
    pair.value = value;
    status.values.push_back(pair);
  }
  diagnostic_msgs::DiagnosticArray message;
  message.header.stamp = stamp;
  message.status.push_back(status);
  return message;
}

}  // namespace ros1
}  // namespace mlndt
