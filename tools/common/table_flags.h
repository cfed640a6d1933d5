#pragma once

// Flags made from a tool's own option table (mlndt/common/option_table.h),
// beside the shared registration flags (option_flags.h): one flag per field,
// named as the field, with the struct's default and the field's FullHelp as
// its --help. A field whose name is a shared flag of the same option
// (--num_threads) is set by that flag. Listed exceptions, so that the option
// reference and the surface test (tests/tools/tool_option_flags_test.cc)
// know them: a field whose name is a shared flag of another option has
// another flag name (MapBuildOptions::voxel_size_m is --voxel_size, as
// --voxel_size_m is the sampling's); a field may be set by a tool flag in
// another unit (MapBuildOptions::max_memory_bytes by mlndt_map's
// --max_memory_gb).
//
// A TableFlags is constructed at namespace scope in a tools/common file that
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
  // {field name, flag name}.
  using Names = std::vector<std::pair<std::string, std::string>>;

  // `tool`: "mlndt_map"; the flags are registered as if defined in
  // tools/<tool>.cc. `renamed`: fields whose flag is not their name;
  // `set_by_tool_flag`: fields without a flag of their own, and the tool's
  // flag (defined in the tool's main) that sets them.
  TableFlags(const OptionTable& table,
             const std::string& tool,
             Names renamed,
             Names set_by_tool_flag);

  const OptionTable& table() const { return table_; }
  const std::string& tool() const { return tool_; }
  const Names& renamed() const { return renamed_; }
  const Names& set_by_tool_flag() const { return set_by_tool_flag_; }
  // The flag that sets field `name`: its own, a shared one, or "" when a
  // tool flag in another unit sets it.
  std::string FlagOf(const std::string& name) const;
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
};

}  // namespace tools
}  // namespace mlndt
