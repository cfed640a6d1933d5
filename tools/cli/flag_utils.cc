#include "tools/cli/flag_utils.h"

#include <gflags/gflags.h>

namespace mlndt {
namespace tools {

bool FlagGiven(const std::string& name) {
  gflags::CommandLineFlagInfo info;
  return gflags::GetCommandLineFlagInfo(name.c_str(), &info) &&
         !info.is_default;
}

std::string GivenFlagName(const std::string& name) { return "--" + name; }

std::string FlagText(const std::string& name) {
  std::string value;
  gflags::GetCommandLineOption(name.c_str(), &value);
  return value;
}

bool RefuseGivenFlags(const std::vector<std::string>& flags,
                      const std::string& reason,
                      std::string* error) {
  for (const std::string& flag : flags) {
    if (FlagGiven(flag)) {
      *error = GivenFlagName(flag) + " " + reason;
      return false;
    }
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
