#pragma once

// ROS 1 bags for tests, written at test time by write_test_bag.py (the real
// python3-rosbag) from PCD files, so no bag is committed.

#include <string>
#include <vector>

#include "lab/io/ros_bag_scans.h"

namespace mlndt {
namespace testing {

// Writes `scans` (PCD files) to the bag `out` on `topic`; `options` are
// write_test_bag.py's (--point_time, --stamps=FILE, --other_topic=NAME).
// False with *error (the script's output) when it fails.
bool WriteTestBag(const std::string& out,
                  const std::string& topic,
                  const std::vector<std::string>& scans,
                  const std::string& options,
                  std::string* error);

}  // namespace testing
}  // namespace mlndt

// Skips the current test when this build reads no ROS bags
// (MLNDT_WITH_ROSBAG=OFF: the ROS 1 packages were not installed).
#define MLNDT_REQUIRE_ROSBAG()                                             \
  if (!::mlndt::RosBagSupported()) {                                       \
    GTEST_SKIP() << "built without ROS bag support (MLNDT_WITH_ROSBAG="    \
                    "OFF; scripts/install_deps.sh installs the packages)"; \
  }
