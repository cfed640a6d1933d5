#include "tests/testing/test_data.h"

#include <cstdlib>
#include <filesystem>

namespace mlndt {
namespace testing {

std::string BundledDataPath(const std::string& relative) {
  return std::string(MLNDT_BUNDLED_DATA_DIR) + "/" + relative;
}

std::string SharedDataDir() {
  const char* dir = std::getenv("MLNDT_DATA_DIR");
  if (dir == nullptr || !std::filesystem::is_directory(dir)) return "";
  return dir;
}

std::string ToolPath(const std::string& name) {
  const char* dir = std::getenv("MLNDT_TOOLS_DIR");
  const std::string tool =
      std::string(dir != nullptr ? dir : MLNDT_TOOLS_DIR) + "/" + name;
  if (std::filesystem::exists(tool)) return tool;
  const char* lab = std::getenv("MLNDT_LAB_PROGRAMS_DIR");
  return std::string(lab != nullptr ? lab : MLNDT_LAB_PROGRAMS_DIR) + "/" +
         name;
}

}  // namespace testing
}  // namespace mlndt
