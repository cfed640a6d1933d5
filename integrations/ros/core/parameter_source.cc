#include "integrations/ros/core/parameter_source.h"

namespace mlndt {
namespace ros_core {

std::vector<std::string> MapParameterSource::Names() const {
  std::vector<std::string> names;
  for (const auto& [name, text] : values_) names.push_back(name);
  return names;
}

bool MapParameterSource::Get(const std::string& name,
                             std::string* text,
                             std::string*) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return false;
  *text = it->second;
  return true;
}

}  // namespace ros_core
}  // namespace mlndt
