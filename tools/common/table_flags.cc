#include "tools/common/table_flags.h"

#include <glog/logging.h>

#include "tools/common/flag_utils.h"
#include "tools/common/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

bool IsShared(const std::string& name) { return FlagOfName(name) != nullptr; }

}  // namespace

TableFlags::TableFlags(const OptionTable& table,
                       const std::string& tool,
                       Names renamed,
                       Names set_by_tool_flag)
    : table_(table),
      tool_(tool),
      file_("tools/" + tool + ".cc"),
      renamed_(std::move(renamed)),
      set_by_tool_flag_(std::move(set_by_tool_flag)) {
  // Leaked on purpose: gflags keeps the file name for the program's life.
  const char* file = (new std::string(file_))->c_str();
  for (const OptionField& field : table_.fields()) {
    CHECK(field.type != OptionType::STRUCT)
        << table_.struct_name() << "." << field.name
        << ": nested structs have their own tables";
    const std::string flag = FlagOf(field.name);
    if (flag.empty() || IsShared(flag)) continue;
    RegisterOptionFlag(flag,
                       field.FullHelp(),
                       file,
                       field.type,
                       field.Format(table_.defaults()));
  }
}

std::string TableFlags::FlagOf(const std::string& name) const {
  for (const auto& [field, flag] : renamed_) {
    if (field == name) return flag;
  }
  for (const auto& [field, flag] : set_by_tool_flag_) {
    if (field == name) return "";
  }
  return name;
}

std::vector<std::string> TableFlags::RegisteredFlags() const {
  std::vector<std::string> flags;
  for (const OptionField& field : table_.fields()) {
    const std::string flag = FlagOf(field.name);
    if (!flag.empty() && !IsShared(flag)) flags.push_back(flag);
  }
  return flags;
}

bool TableFlags::Apply(void* s, std::string* error) const {
  for (const OptionField& field : table_.fields()) {
    const std::string flag = FlagOf(field.name);
    if (flag.empty() || !FlagGiven(flag)) continue;
    const std::string text = FlagText(flag);
    if (!field.Parse(text, s, error)) {
      *error = GivenFlagName(flag) + "=" + text + ": " + *error;
      return false;
    }
    std::string why;
    if (!field.CheckRange(s, "", &why)) {
      *error = GivenFlagName(flag) + " must be " + field.range.ToString() +
               (field.unit.empty() ? "" : " (" + field.unit + ")") + ", not " +
               text;
      return false;
    }
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
