#include "integrations/ros/core/option_parameters.h"

#include <glog/logging.h>

#include <algorithm>

namespace mlndt {
namespace ros_core {
namespace {

// The field at `path` of the struct `root` (of `table`) and the struct that
// holds it.
const OptionField* Locate(const OptionTable& table,
                          const std::string& path,
                          const void* root,
                          const void** owner) {
  const OptionField* field = table.FindPath(path, root, owner);
  CHECK(field != nullptr) << table.struct_name() << " has no field " << path;
  return field;
}

}  // namespace

void OptionParameters::Add(const std::string& name,
                           int root,
                           const std::string& path) {
  CHECK(root >= 0 && root < static_cast<int>(roots_.size())) << name;
  const OptionField* field = roots_[root]->FindPath(path);
  CHECK(field != nullptr) << roots_[root]->struct_name() << " has no field "
                          << path;
  for (OptionParameter& p : parameters_) {
    if (p.name != name) continue;
    CHECK(p.field->type == field->type) << name << ": fields of two types";
    p.targets.push_back({root, path});
    return;
  }
  parameters_.push_back({name, field, {{root, path}}});
}

const OptionParameter* OptionParameters::Find(const std::string& name) const {
  for (const OptionParameter& p : parameters_) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::string OptionParameters::DefaultText(const OptionParameter& p) const {
  const OptionParameter::Target& target = p.targets.front();
  const OptionTable& table = *roots_[target.root];
  const void* owner = nullptr;
  return Locate(table, target.path, table.defaults(), &owner)->Format(owner);
}

bool OptionParameters::Apply(const ParameterSource& source,
                             const std::vector<void*>& roots,
                             std::string* error) const {
  CHECK_EQ(roots.size(), roots_.size());
  for (const OptionParameter& p : parameters_) {
    std::string text;
    error->clear();
    if (!source.Get(p.name, &text, error)) {
      if (!error->empty()) return false;
      continue;
    }
    for (const OptionParameter::Target& target : p.targets) {
      const void* owner = nullptr;
      const OptionField* field =
          Locate(*roots_[target.root], target.path, roots[target.root], &owner);
      void* mutable_owner = const_cast<void*>(owner);
      std::string why;
      if (!field->Parse(text, mutable_owner, &why)) {
        *error = "~" + p.name + "=" + text + ": " + why;
        return false;
      }
      if (!field->CheckRange(mutable_owner, "", &why)) {
        *error = "~" + p.name + "=" + text + ": must be " +
                 field->range.ToString() +
                 (field->unit.empty() ? "" : " (" + field->unit + ")");
        return false;
      }
    }
  }
  return true;
}

bool CheckKnownParameters(
    const ParameterSource& source,
    const OptionParameters& options,
    const std::vector<std::string>& known,
    const std::vector<std::pair<std::string, std::string>>& refused,
    std::string* error) {
  for (const std::string& name : source.Names()) {
    for (const auto& [refused_name, reason] : refused) {
      if (name == refused_name) {
        *error = "~" + name + " does not apply: " + reason;
        return false;
      }
    }
    if (options.Find(name) != nullptr ||
        std::find(known.begin(), known.end(), name) != known.end()) {
      continue;
    }
    *error = "~" + name +
             " is not a parameter of this node (the parameters are the "
             "tool's flags; see docs/ros.md)";
    return false;
  }
  return true;
}

bool GetText(const ParameterSource& source,
             const std::string& name,
             std::string* text,
             std::string* error) {
  std::string value;
  error->clear();
  if (!source.Get(name, &value, error)) return error->empty();
  *text = value;
  return true;
}

}  // namespace ros_core
}  // namespace mlndt
