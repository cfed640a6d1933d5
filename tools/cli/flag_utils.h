#pragma once

// Whether a gflags flag was given on the command line, its value, and
// refusing flags a tool (or one of its modes) does not read, so that none is
// silently ignored.

#include <string>
#include <vector>

namespace mlndt {
namespace tools {

// True when --<name> is a defined flag that was given on the command line.
bool FlagGiven(const std::string& name);

// "--<name>".
std::string GivenFlagName(const std::string& name);

// The value of --<name> as text.
std::string FlagText(const std::string& name);

// False with *error ("--<flag> <reason>") for the first of `flags` given on
// the command line.
bool RefuseGivenFlags(const std::vector<std::string>& flags,
                      const std::string& reason,
                      std::string* error);

}  // namespace tools
}  // namespace mlndt
