#include "tools/cli/input_files.h"

#include <gflags/gflags.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "mlndt/cloud/cloud_format.h"

namespace mlndt {
namespace tools {
namespace {

std::vector<std::string>& ToolArguments() {
  static std::vector<std::string> arguments;
  return arguments;
}

bool IsOutputFlag(const std::string& name) {
  return name.rfind("output", 0) == 0 || name == "out" || name == "gnuplot";
}

// The paths one flag value may name: itself, its comma-separated parts, and
// each part after a "kind:" prefix.
std::vector<std::string> Candidates(const std::string& value) {
  std::vector<std::string> out = {value};
  size_t start = 0;
  while (start <= value.size()) {
    const size_t comma = std::min(value.find(',', start), value.size());
    const std::string part = value.substr(start, comma - start);
    if (!part.empty() && part != value) out.push_back(part);
    const size_t colon = part.find(':');
    if (colon != std::string::npos) out.push_back(part.substr(colon + 1));
    start = comma + 1;
  }
  return out;
}

bool SameFile(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// The input `candidate` is `output` (`output_status`: its stat), or a
// folder whose point-cloud files `output` is one of.
bool IsInput(const std::string& candidate,
             const std::string& output,
             const struct stat& output_status) {
  struct stat status;
  if (candidate.empty() || ::stat(candidate.c_str(), &status) != 0) {
    return false;
  }
  if (S_ISREG(status.st_mode)) return SameFile(status, output_status);
  if (!S_ISDIR(status.st_mode)) return false;
  std::string parent = std::filesystem::path(output).parent_path().string();
  if (parent.empty()) parent = ".";
  struct stat parent_status;
  CloudFormat format;
  std::string ignored;
  return ::stat(parent.c_str(), &parent_status) == 0 &&
         SameFile(parent_status, status) &&
         CloudFormatFromPath(output, &format, &ignored);
}

// "the argument A" or "--name=value" for the first recorded argument or
// string flag other than the outputs (one of its Candidates) that
// `is_input` accepts; "" when none.
std::string FindInput(const std::function<bool(const std::string&)>& is_input) {
  for (const std::string& argument : ToolArguments()) {
    if (is_input(argument)) return "the argument " + argument;
  }
  std::vector<gflags::CommandLineFlagInfo> flags;
  gflags::GetAllFlags(&flags);
  for (const gflags::CommandLineFlagInfo& info : flags) {
    if (info.type != "string" || IsOutputFlag(info.name)) continue;
    for (const std::string& candidate : Candidates(info.current_value)) {
      if (is_input(candidate))
        return "--" + info.name + "=" + info.current_value;
    }
  }
  return "";
}

}  // namespace

void SetToolArguments(const std::vector<std::string>& arguments) {
  ToolArguments() = arguments;
}

bool CheckNotAnInput(const std::string& flag,
                     const std::string& path,
                     std::string* error) {
  struct stat output_status;
  if (path.empty() || ::stat(path.c_str(), &output_status) != 0 ||
      !S_ISREG(output_status.st_mode)) {
    return true;  // Nothing there (or not a file): nothing to overwrite.
  }
  const std::string input = FindInput([&](const std::string& candidate) {
    return IsInput(candidate, path, output_status);
  });
  if (input.empty()) return true;
  *error = "--" + flag + "=" + path +
           ": refusing to overwrite an input of this run (" + input + ")";
  return false;
}

bool CheckNotAnInputFolder(const std::string& flag,
                           const std::string& dir,
                           std::string* error) {
  struct stat dir_status;
  if (dir.empty() || ::stat(dir.c_str(), &dir_status) != 0 ||
      !S_ISDIR(dir_status.st_mode)) {
    return true;  // Not there yet: no input lies in it.
  }
  const std::string input = FindInput([&](const std::string& candidate) {
    struct stat status;
    return !candidate.empty() && ::stat(candidate.c_str(), &status) == 0 &&
           S_ISDIR(status.st_mode) && SameFile(status, dir_status);
  });
  if (input.empty()) return true;
  *error = "--" + flag + "=" + dir + ": is a folder this run reads (" + input +
           "); write the outputs elsewhere (the next run would read them as "
           "inputs)";
  return false;
}

}  // namespace tools
}  // namespace mlndt
