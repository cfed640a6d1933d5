#include "integrations/ros/src/ros_parameter_source.h"

#include <xmlrpcpp/XmlRpcValue.h>

#include <cstdio>

namespace mlndt {
namespace ros1 {
namespace {

// A scalar's text; false for a dictionary, binary or date.
bool ScalarText(XmlRpc::XmlRpcValue& value, std::string* text) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      *text = static_cast<bool>(value) ? "true" : "false";
      return true;
    case XmlRpc::XmlRpcValue::TypeInt:
      *text = std::to_string(static_cast<int>(value));
      return true;
    case XmlRpc::XmlRpcValue::TypeDouble: {
      char number[64];
      std::snprintf(
          number, sizeof(number), "%.17g", static_cast<double>(value));
      *text = number;
      return true;
    }
    case XmlRpc::XmlRpcValue::TypeString:
      *text = static_cast<std::string>(value);
      return true;
    default:
      return false;
  }
}

}  // namespace

std::vector<std::string> RosParameterSource::Names() const {
  std::vector<std::string> all;
  node_.getParamNames(all);
  const std::string prefix = node_.getNamespace() + "/";
  std::vector<std::string> names;
  for (const std::string& name : all) {
    if (name.rfind(prefix, 0) == 0) names.push_back(name.substr(prefix.size()));
  }
  return names;
}

bool RosParameterSource::Get(const std::string& name,
                             std::string* text,
                             std::string* error) const {
  XmlRpc::XmlRpcValue value;
  if (!node_.getParam(name, value)) return false;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeArray) {
    std::string joined;
    for (int i = 0; i < value.size(); ++i) {
      std::string item;
      if (!ScalarText(value[i], &item)) {
        *error = "~" + name + ": a list of numbers or names is expected";
        return false;
      }
      joined += (i == 0 ? "" : ",") + item;
    }
    *text = joined;
    return true;
  }
  if (!ScalarText(value, text)) {
    *error = "~" + name + ": a bool, number, text or list is expected";
    return false;
  }
  return true;
}

}  // namespace ros1
}  // namespace mlndt
