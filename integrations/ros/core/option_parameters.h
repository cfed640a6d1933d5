#pragma once

// A node's parameters made from option tables (mlndt/common/option_table.h)
// under the tools' flag names: a parameter is named as the flag that sets
// the same field (tools/cli/option_flags.h for the registration's
// fields, tools/cli/table_flags.h for a tool's own table), so
// `rosparam set ~gate_factor 4` means what `mlndt_odometry --gate_factor=4`
// means. Nothing is listed by hand: the parameters are the tables' fields.
//
// A parameter sets one field or more ("targets"): each target is a field
// path inside one of the structs ("roots") the node configures, e.g.
// OdometryOptions (root 0) and its RegistrationOptions (root 1). Values
// are parsed by the field (OptionField::Parse) and checked against its
// range (OptionField::CheckRange) at start, before any work.

#include <string>
#include <vector>

#include "integrations/ros/core/parameter_source.h"
#include "mlndt/common/option_table.h"

namespace mlndt {
namespace ros_core {

struct OptionParameter {
  struct Target {
    int root = 0;      // Index into Apply's roots.
    std::string path;  // "local_map.max_keyframes".
  };
  std::string name;  // "local_map_max_keyframes".
  // The first target's field: its type, unit, range and help.
  const OptionField* field = nullptr;
  std::vector<Target> targets;
};

class OptionParameters {
 public:
  // `roots`: the table of each root struct, by index.
  explicit OptionParameters(std::vector<const OptionTable*> roots)
      : roots_(std::move(roots)) {}

  // Adds a parameter `name` that sets `path` of root `root`; a name added
  // before gets one more target.
  void Add(const std::string& name, int root, const std::string& path);

  const std::vector<OptionParameter>& parameters() const { return parameters_; }
  const OptionParameter* Find(const std::string& name) const;
  // The default of parameter `p` as text: its first target's field in the
  // root's default struct.
  std::string DefaultText(const OptionParameter& p) const;

  // Sets the targets of every parameter `source` has, in the structs
  // `roots` points to (same order and types as the tables). False with
  // *error naming the parameter ("~gate_factor=0.5: must be in [1, inf)",
  // "~sampling=grid: expected one of: ...").
  bool Apply(const ParameterSource& source,
             const std::vector<void*>& roots,
             std::string* error) const;

 private:
  std::vector<const OptionTable*> roots_;
  std::vector<OptionParameter> parameters_;
};

// False with *error naming the first parameter `source` has that is
// neither in `known` nor a parameter of `options` (a typing error would
// otherwise be ignored). `refused`: {name, reason} of parameters the node
// refuses with a reason ("the map file fixes the cells").
bool CheckKnownParameters(
    const ParameterSource& source,
    const OptionParameters& options,
    const std::vector<std::string>& known,
    const std::vector<std::pair<std::string, std::string>>& refused,
    std::string* error);

// The text of parameter `name` into *text when set (else *text is left);
// false with *error when it is set with no text form.
bool GetText(const ParameterSource& source,
             const std::string& name,
             std::string* text,
             std::string* error);

}  // namespace ros_core
}  // namespace mlndt
