#include "tests/testing/scratch_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <set>

namespace mlndt {
namespace testing {

std::string TestScratchDir() {
  const ::testing::TestInfo* test =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name =
      test == nullptr
          ? std::string("static")
          : std::string(test->test_suite_name()) + "_" + test->name();
  const std::string dir =
      ::testing::TempDir() + "mlndt_" + name + "_" + std::to_string(::getpid());
  static std::mutex mutex;
  static std::set<std::string> made;
  std::lock_guard<std::mutex> lock(mutex);
  if (made.insert(dir).second) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  return dir;
}

std::string ScratchPath(const std::string& name) {
  return TestScratchDir() + "/" + name;
}

}  // namespace testing
}  // namespace mlndt
