#pragma once

// Whether a gflags flag was given on the command line, its value, and
// refusing flags a tool (or one of its modes) does not read, so that none is
// silently ignored. A flag renamed to its option field's name keeps its old
// name as a deprecated alias (RegisterFlagAlias): giving the alias counts as
// giving the flag, with the alias's value, and messages name the flag as the
// user typed it.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// Makes --<alias> (a flag of the same type, defined by the caller) a
// deprecated name of --<name>.
void RegisterFlagAlias(const std::string& alias, const std::string& name);

// True when --<name> (or its alias) is a defined flag that was given on the
// command line. Prints a one-line deprecation notice to stderr the first
// time an alias is found given.
bool FlagGiven(const std::string& name);

// "--<name>", or "--<alias>" when the alias was given.
std::string GivenFlagName(const std::string& name);

// The value of --<name> as text (of its alias when that was given).
std::string FlagText(const std::string& name);

// False with *error naming both when a flag and its alias were given.
bool CheckFlagAliases(std::string* error);

// False with *error ("--<flag> <reason>") for the first of `flags` given on
// the command line.
bool RefuseGivenFlags(const std::vector<std::string>& flags,
                      const std::string& reason,
                      std::string* error);

}  // namespace tools
}  // namespace mlndt
