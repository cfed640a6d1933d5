#pragma once

// Where tests find real data.
//  - Bundled data (data/ in the repository) is always there.
//  - The larger shared data set is named by the environment variable
//    MLNDT_DATA_DIR (.ci/run points it at ../shared/data); tests that need it
//    skip with a message saying so when it is unset.

#include <string>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {
namespace testing {

// Absolute path of `relative` inside the repository's data/ folder.
std::string BundledDataPath(const std::string& relative);

// The cloud at BundledDataPath(relative); a test failure naming the file
// (and an empty cloud) when it cannot be read.
PointCloud LoadBundledCloud(const std::string& relative);

// The folder named by MLNDT_DATA_DIR, or "" when it is unset or missing.
std::string SharedDataDir();

// Absolute path of the lab's program of that name (e.g. "mlndt_suite", in
// build/lab/programs/, or MLNDT_LAB_PROGRAMS_DIR when set) or, when there is
// no such program, of the built tool (e.g. "mlndt_info", in build/tools/, or
// MLNDT_TOOLS_DIR when set).
std::string ToolPath(const std::string& name);

}  // namespace testing
}  // namespace mlndt

// Skips the current test, saying why, when MLNDT_DATA_DIR is not set.
#define MLNDT_REQUIRE_SHARED_DATA(dir_variable)                           \
  const std::string dir_variable = ::mlndt::testing::SharedDataDir();     \
  if (dir_variable.empty()) {                                             \
    GTEST_SKIP() << "MLNDT_DATA_DIR is not set (or not a folder): this "  \
                    "test needs the shared LiDAR data set; .ci/run sets " \
                    "it to ../shared/data";                               \
  }
