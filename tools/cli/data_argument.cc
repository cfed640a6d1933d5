#include "tools/cli/data_argument.h"

#include <gflags/gflags.h>

#include <ctime>
#include <filesystem>
#include <iostream>

namespace mlndt {
namespace tools {
namespace {

bool HasFlag(const char* name, gflags::CommandLineFlagInfo* info) {
  return gflags::GetCommandLineFlagInfo(name, info);
}

// "<tool>_20261207_214501": the run's UTC time, to the second.
std::string DefaultOutputDir(const std::string& tool) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof(stamp), "_%Y%m%d_%H%M%S", &utc);
  return tool + stamp;
}

bool TakeDataPath(const std::string& path,
                  const gflags::CommandLineFlagInfo& scans,
                  const gflags::CommandLineFlagInfo& bag,
                  std::string* error) {
  if (!scans.current_value.empty() || !bag.current_value.empty()) {
    *error = "the data '" + path +
             "' is given as an argument and as --scans or --bag: give one";
    return false;
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    gflags::SetCommandLineOption("scans", path.c_str());
  } else if (std::filesystem::is_regular_file(path, ec)) {
    gflags::SetCommandLineOption("bag", path.c_str());
  } else {
    *error = "the data argument '" + path +
             "' is neither a folder of scans nor a bag file";
    return false;
  }
  return true;
}

}  // namespace

bool ApplyDataArgument(const std::string& tool,
                       int* argc,
                       char** argv,
                       std::string* error) {
  gflags::CommandLineFlagInfo scans, bag, output_dir;
  if (!HasFlag("scans", &scans) || !HasFlag("bag", &bag) ||
      !HasFlag("output_dir", &output_dir)) {
    return true;
  }
  if (*argc == 2) {
    if (!TakeDataPath(argv[1], scans, bag, error)) return false;
    *argc = 1;
  }
  if (output_dir.current_value.empty()) {
    const std::string dir = DefaultOutputDir(tool);
    gflags::SetCommandLineOption("output_dir", dir.c_str());
    std::cerr << tool << ": --output_dir=" << dir << " (no --output_dir given)"
              << std::endl;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
