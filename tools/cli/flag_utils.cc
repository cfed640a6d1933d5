#include "tools/cli/flag_utils.h"

#include <gflags/gflags.h>

#include <iostream>
#include <map>
#include <set>

namespace mlndt {
namespace tools {
namespace {

// Flag name -> its deprecated alias.
std::map<std::string, std::string>& Aliases() {
  static std::map<std::string, std::string> aliases;
  return aliases;
}

bool GivenAsIs(const std::string& name) {
  gflags::CommandLineFlagInfo info;
  return gflags::GetCommandLineFlagInfo(name.c_str(), &info) &&
         !info.is_default;
}

// The alias of `name` when it was given, else "".
std::string GivenAlias(const std::string& name) {
  const auto it = Aliases().find(name);
  if (it == Aliases().end() || !GivenAsIs(it->second)) return "";
  static std::set<std::string> noticed;
  if (noticed.insert(it->second).second) {
    std::cerr << "note: --" << it->second << " is deprecated; it is --" << name
              << " now\n";
  }
  return it->second;
}

}  // namespace

void RegisterFlagAlias(const std::string& alias, const std::string& name) {
  Aliases()[name] = alias;
}

bool FlagGiven(const std::string& name) {
  return GivenAsIs(name) || !GivenAlias(name).empty();
}

std::string GivenFlagName(const std::string& name) {
  const std::string alias = GivenAlias(name);
  return "--" + (alias.empty() || GivenAsIs(name) ? name : alias);
}

std::string FlagText(const std::string& name) {
  const std::string alias = GivenAlias(name);
  std::string value;
  gflags::GetCommandLineOption(
      (alias.empty() || GivenAsIs(name) ? name : alias).c_str(), &value);
  return value;
}

bool CheckFlagAliases(std::string* error) {
  for (const auto& [name, alias] : Aliases()) {
    if (GivenAsIs(name) && GivenAsIs(alias)) {
      *error = "--" + alias + " and --" + name + " set the same option (--" +
               alias + " is its deprecated name); give --" + name + " only";
      return false;
    }
  }
  return true;
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
