#include "tools/cli/grid_flags.h"

#include <gflags/gflags.h>

#include "tools/cli/flag_utils.h"
#include "tools/cli/option_flags.h"

namespace mlndt {
namespace tools {
namespace {

bool IsGridFlag(const OptionFlag& flag) {
  return flag.mlndt_path.rfind("grid.", 0) == 0;
}

// The shared flags of LayeredGridOptions' fields.
std::vector<std::string> GridFlags() {
  std::vector<std::string> flags;
  for (const OptionFlag& flag : OptionFlags()) {
    if (IsGridFlag(flag)) flags.push_back(flag.name);
  }
  return flags;
}

}  // namespace

std::vector<std::string> NonGridFlags() {
  std::vector<std::string> flags;
  for (const OptionFlag& flag : OptionFlags()) {
    if (!IsGridFlag(flag)) flags.push_back(flag.name);
  }
  return flags;
}

void SetGridFlagDefaults(const LayeredGridOptions& base) {
  for (const OptionFlag& flag : OptionFlags()) {
    if (!IsGridFlag(flag)) continue;
    const void* owner = nullptr;
    const OptionField* field = LayeredGridOptionsTable().FindPath(
        flag.mlndt_path.substr(std::string("grid.").size()), &base, &owner);
    gflags::SetCommandLineOptionWithMode(flag.name.c_str(),
                                         field->Format(owner).c_str(),
                                         gflags::SET_FLAGS_DEFAULT);
  }
}

bool GridFlagsGiven() {
  for (const std::string& flag : GridFlags()) {
    if (FlagGiven(flag)) return true;
  }
  return false;
}

bool ApplyGridFlags(const std::string& tool,
                    LayeredGridOptions* grid,
                    std::string* error) {
  if (!RefuseGivenFlags(
          NonGridFlags(),
          "does not apply to " + tool + " (it reads only the map's flags)",
          error) ||
      !ApplyGivenFlags(
          LayeredGridOptionsTable(), "grid.", false, grid, error)) {
    return false;
  }
  if (FlagGiven("num_layers") && grid->finest_cell_size_m > 0.0) {
    *error = "give --num_layers or " + GivenFlagName("finest_cell_size_m") +
             ", not both";
    return false;
  }
  std::string why;
  if (!grid->IsValid(&why)) {
    *error = "invalid map options: " + why;
    return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
