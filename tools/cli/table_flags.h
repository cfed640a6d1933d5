#pragma once

// Flags made from a tool's own option table (mlndt/common/option_table.h),
// beside the shared registration flags (option_flags.h): one flag per field,
// named as the field (a nested struct's field by its path with '_' for '.':
// OdometryOptions::local_map.max_keyframes is --local_map_max_keyframes),
// with the struct's default and the field's FullHelp as its --help. A field
// whose name is a shared flag of the same option (--num_threads) is set by
// that flag. Listed exceptions, so that the option reference and the surface
// test (tests/tools/tool_option_flags_test.cc) know them: a field whose name
// is a shared flag of another option has another flag name
// (MapBuildOptions::voxel_size_m is --voxel_size, as --voxel_size_m is the
// sampling's); a field may be set by a tool flag in another unit
// (MapBuildOptions::max_memory_bytes by mlndt_map's --max_memory_gb). A flag
// has one name: no older names are kept.
//
// A TableFlags is constructed at namespace scope in a tools/cli file that
// only its tool links (map_build_flags.cc, localizer_flags.cc): its flags
// are registered at static-initialisation time and --help shows them among
// the tool's own flags.

#include <string>
#include <utility>
#include <vector>

#include "mlndt/common/option_table.h"

namespace mlndt {
namespace tools {

class TableFlags {
 public:
  // {field path, flag name}.
  using Names = std::vector<std::pair<std::string, std::string>>;
  // Whether a flag name is a shared registration flag (IsSharedFlag of
  // option_flags.h, which links them); nullptr for a tool without them.
  using IsShared = bool (*)(const std::string& name);

  // A field of the table or of a struct nested in it.
  struct Field {
    std::string path;  // "local_map.max_keyframes".
    const OptionField* field = nullptr;
  };

  // `tool`: "mlndt_map"; the flags are registered as if defined in
  // tools/<tool>.cc. `renamed`: fields whose flag is not their path's;
  // `set_by_tool_flag`: fields without a flag of their own, and the tool's
  // flag (defined in the tool's main) that sets them; `is_shared`: see
  // IsShared.
  TableFlags(const OptionTable& table,
             const std::string& tool,
             Names renamed,
             Names set_by_tool_flag,
             IsShared is_shared);

  const OptionTable& table() const { return table_; }
  const std::string& tool() const { return tool_; }
  const Names& renamed() const { return renamed_; }
  const Names& set_by_tool_flag() const { return set_by_tool_flag_; }
  // Every field with a value (nested structs' fields, not the structs).
  const std::vector<Field>& fields() const { return fields_; }
  // The struct inside *s (of the table's type) that holds field `path`.
  const void* Owner(const std::string& path, const void* s) const;
  // The flag that sets field `path`: its own, a shared one, or "" when a
  // tool flag in another unit sets it.
  std::string FlagOf(const std::string& path) const;
  // Whether `flag` is a shared registration flag (not registered here).
  bool Shared(const std::string& flag) const;
  // The flags registered here.
  std::vector<std::string> RegisteredFlags() const;

  // Sets the fields of *s (a struct of the table's type) from the flags
  // given and checks their ranges; false with *error naming the flag as
  // given ("--voxel_size=x: expected a number", "--voxel_size must be in
  // [0.001, 1000] or 0 (m), not -1").
  bool Apply(void* s, std::string* error) const;

 private:
  const OptionTable& table_;
  std::string tool_;
  std::string file_;
  Names renamed_;
  Names set_by_tool_flag_;
  IsShared is_shared_;
  std::vector<Field> fields_;
};

}  // namespace tools
}  // namespace mlndt
