#include "tools/cli/map_flags.h"

#include <gflags/gflags.h>

#include "tools/cli/option_flags.h"
#include "tools/cli/registration_flags.h"

namespace mlndt {
namespace tools {
namespace {

// The flags of the map's options (grid.*).
std::vector<std::string> MapFlags() {
  std::vector<std::string> flags;
  for (const OptionFlag& flag : OptionFlags()) {
    if (flag.mlndt_path.rfind("grid.", 0) == 0) flags.push_back(flag.name);
  }
  return flags;
}

// The shared flags a localizer (a map file, ML-NDT) refuses: the map's and
// conventional NDT's own.
std::vector<std::string> LocalizerRefused() {
  std::vector<std::string> flags = MapFlags();
  for (const OptionFlag& flag : OptionFlags()) {
    if (flag.mlndt_path.empty()) flags.push_back(flag.name);
  }
  return flags;
}

// The shared registration flags a map build does not read (the map's, the
// range filter's, --num_threads and --preset it does).
std::vector<std::string> RegistrationOnly() {
  std::vector<std::string> flags = {"method", "initial_uncertainty"};
  for (const OptionFlag& flag : OptionFlags()) {
    const std::string& path =
        flag.mlndt_path.empty() ? flag.ndt_path : flag.mlndt_path;
    if (path.rfind("grid.", 0) != 0 && path.rfind("range_filter.", 0) != 0 &&
        path != "num_threads") {
      flags.push_back(flag.name);
    }
  }
  return flags;
}

const std::vector<std::string>& MapFlagList() {
  static const std::vector<std::string> flags = MapFlags();
  return flags;
}

}  // namespace

bool GridOptionsFromFlags(const std::string& tool,
                          LayeredGridOptions* grid,
                          std::string* error) {
  if (!RefuseGivenFlags(MapBuildRefusedFlags(),
                        "does not apply to " + tool +
                            " (it builds a map; registration flags belong "
                            "to mlndt_localize)",
                        error)) {
    return false;
  }
  if (FLAGS_preset == "paper") {
    *grid = PaperLayeredGridOptions();
  } else if (FLAGS_preset == "default") {
    *grid = LayeredGridOptions();
  } else {
    *error = "--preset=" + FLAGS_preset + ": expected default or paper";
    return false;
  }
  if (!ApplyGivenFlags(
          LayeredGridOptionsTable(), "grid.", false, grid, error)) {
    return false;
  }
  if (!CheckLayerCountFlags(grid->finest_cell_size_m, error)) return false;
  std::string why;
  if (grid->IsValid(&why)) return true;
  // Name the flag behind the option ("regularization.min_eigenvalue_m2").
  for (const std::string& flag : MapFlagList()) {
    const OptionFlag& option = *FlagOfName(flag);
    const std::string field =
        option.mlndt_path.substr(option.mlndt_path.rfind('.') + 1);
    if (why.find(field + " =") != std::string::npos) {
      *error = GivenFlagName(flag) + ": " + why;
      return false;
    }
  }
  *error = why;
  return false;
}

const std::vector<std::string>& MapBuildRefusedFlags() {
  static const std::vector<std::string> flags = RegistrationOnly();
  return flags;
}

const std::vector<std::string>& LocalizerRefusedFlags() {
  static const std::vector<std::string> flags = LocalizerRefused();
  return flags;
}

bool RefuseMapFlags(const std::string& tool, std::string* error) {
  return RefuseGivenFlags(MapFlagList(),
                          "does not apply to " + tool +
                              ": the map file fixes the cells (build the map "
                              "with mlndt_map to change them)",
                          error);
}

}  // namespace tools
}  // namespace mlndt
