#pragma once

// The node's private parameters (~name) on the ROS 1 parameter server as a
// ParameterSource (core/parameter_source.h): XmlRpc values as text (bools
// true/false, ints, doubles to 17 digits, strings, lists comma-separated).

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "integrations/ros/core/parameter_source.h"

namespace mlndt {
namespace ros1 {

class RosParameterSource : public ros_core::ParameterSource {
 public:
  // `private_node`: the node's private handle (ros::NodeHandle("~")).
  explicit RosParameterSource(const ros::NodeHandle& private_node)
      : node_(private_node) {}

  std::vector<std::string> Names() const override;
  bool Get(const std::string& name,
           std::string* text,
           std::string* error) const override;

 private:
  ros::NodeHandle node_;
};

}  // namespace ros1
}  // namespace mlndt
