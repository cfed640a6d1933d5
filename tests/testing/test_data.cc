#include "tests/testing/test_data.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "mlndt/cloud/io.h"

namespace mlndt {
namespace testing {

std::string BundledDataPath(const std::string& relative) {
  return std::string(MLNDT_BUNDLED_DATA_DIR) + "/" + relative;
}

PointCloud LoadBundledCloud(const std::string& relative) {
  PointCloud cloud;
  std::string error;
  if (!ReadPointCloud(BundledDataPath(relative), &cloud, nullptr, &error)) {
    ADD_FAILURE() << error;
  }
  return cloud;
}

std::string SharedDataDir() {
  const char* dir = std::getenv("MLNDT_DATA_DIR");
  if (dir == nullptr || !std::filesystem::is_directory(dir)) return "";
  return dir;
}

std::string ToolPath(const std::string& name) {
  // The lab's programs first: a build folder from before they moved out of
  // tools/ still holds stale copies there.
  const char* lab = std::getenv("MLNDT_LAB_PROGRAMS_DIR");
  const std::string program =
      std::string(lab != nullptr ? lab : MLNDT_LAB_PROGRAMS_DIR) + "/" + name;
  if (std::filesystem::exists(program)) return program;
  const char* dir = std::getenv("MLNDT_TOOLS_DIR");
  return std::string(dir != nullptr ? dir : MLNDT_TOOLS_DIR) + "/" + name;
}

}  // namespace testing
}  // namespace mlndt
