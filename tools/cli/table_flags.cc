#include "tools/cli/table_flags.h"

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "tools/cli/flag_utils.h"
#include "tools/cli/option_flags_store.h"
#include "tools/cli/tool_main.h"

namespace mlndt {
namespace tools {
namespace {

void CollectFields(const OptionTable& table,
                   const std::string& prefix,
                   std::vector<TableFlags::Field>* fields) {
  for (const OptionField& field : table.fields()) {
    if (field.type == OptionType::STRUCT) {
      CollectFields(*field.nested, prefix + field.name + ".", fields);
    } else {
      fields->push_back({prefix + field.name, &field});
    }
  }
}

std::string Underscored(std::string path) {
  for (char& c : path) {
    if (c == '.') c = '_';
  }
  return path;
}

}  // namespace

TableFlags::TableFlags(const OptionTable& table,
                       const std::string& tool,
                       Names renamed,
                       Names set_by_tool_flag,
                       IsShared is_shared)
    : table_(table),
      tool_(tool),
      file_(MainFile(tool)),
      renamed_(std::move(renamed)),
      set_by_tool_flag_(std::move(set_by_tool_flag)),
      is_shared_(is_shared) {
  CollectFields(table_, "", &fields_);
  // Leaked on purpose: gflags keeps the file name for the program's life.
  const char* file = (new std::string(file_))->c_str();
  for (const Field& f : fields_) {
    const std::string flag = FlagOf(f.path);
    if (flag.empty() || Shared(flag)) continue;
    const std::string value = f.field->Format(Owner(f.path, table_.defaults()));
    RegisterOptionFlag(flag, f.field->FullHelp(), file, f.field->type, value);
  }
}

const void* TableFlags::Owner(const std::string& path, const void* s) const {
  const void* owner = nullptr;
  CHECK(table_.FindPath(path, s, &owner) != nullptr)
      << table_.struct_name() << " has no field " << path;
  return owner;
}

bool TableFlags::Shared(const std::string& flag) const {
  return is_shared_ != nullptr && is_shared_(flag);
}

std::string TableFlags::FlagOf(const std::string& path) const {
  for (const auto& [field, flag] : renamed_) {
    if (field == path) return flag;
  }
  for (const auto& [field, flag] : set_by_tool_flag_) {
    if (field == path) return "";
  }
  return Underscored(path);
}

std::vector<std::string> TableFlags::RegisteredFlags() const {
  std::vector<std::string> flags;
  for (const Field& f : fields_) {
    const std::string flag = FlagOf(f.path);
    if (!flag.empty() && !Shared(flag)) flags.push_back(flag);
  }
  return flags;
}

bool TableFlags::Apply(void* s, std::string* error) const {
  for (const Field& f : fields_) {
    const std::string flag = FlagOf(f.path);
    if (flag.empty() || !FlagGiven(flag)) continue;
    void* owner = const_cast<void*>(Owner(f.path, s));
    const std::string text = FlagText(flag);
    if (!f.field->Parse(text, owner, error)) {
      *error = GivenFlagName(flag) + "=" + text + ": " + *error;
      return false;
    }
    std::string why;
    if (!f.field->CheckRange(owner, "", &why)) {
      *error = GivenFlagName(flag) + " must be " + f.field->range.ToString() +
               (f.field->unit.empty() ? "" : " (" + f.field->unit + ")") +
               ", not " + text;
      return false;
    }
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
