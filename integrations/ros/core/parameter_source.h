#pragma once

// Where a node's parameters come from, without the middleware: the ROS 1
// parameter server (src/ros_parameter_source.h), a ROS 2 node's
// parameters, or a map in tests. Values are text as the tools' flags take
// them: bools true/false, numbers, lists comma-separated, enums by name.

#include <map>
#include <string>
#include <vector>

namespace mlndt {
namespace ros_core {

class ParameterSource {
 public:
  virtual ~ParameterSource() = default;
  // The names of the parameters set (relative to the node's namespace).
  virtual std::vector<std::string> Names() const = 0;
  // False when `name` is not set (*error left empty), or when its value
  // has no text form (a dictionary; *error says so).
  virtual bool Get(const std::string& name,
                   std::string* text,
                   std::string* error) const = 0;
};

// Parameters from a name -> text map (tests, command lines).
class MapParameterSource : public ParameterSource {
 public:
  MapParameterSource() = default;
  explicit MapParameterSource(std::map<std::string, std::string> values)
      : values_(std::move(values)) {}

  void Set(const std::string& name, const std::string& text) {
    values_[name] = text;
  }
  std::vector<std::string> Names() const override;
  bool Get(const std::string& name,
           std::string* text,
           std::string* error) const override;

 private:
  std::map<std::string, std::string> values_;
};

}  // namespace ros_core
}  // namespace mlndt
