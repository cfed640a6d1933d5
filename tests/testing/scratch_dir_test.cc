// Test folders are per test and per process (issue 27, item 17): under
// ctest -j two processes running a test of the same name, or two tests of
// one name in different suites, never share (and so never delete or
// overwrite) each other's files.

#include "tests/testing/scratch_dir.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/testing/run_tool.h"

namespace mlndt {
namespace testing {
namespace {

namespace fs = std::filesystem;

// Runs `make_dir` in a child process, which writes its own file there;
// the parent's file in its own folder must survive.
template <typename MakeDir>
void ExpectChildDoesNotTouchOurFolder(MakeDir make_dir) {
  const std::string ours = make_dir();
  std::ofstream(ours + "/large_coordinates_reference.pcd") << "parent";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string theirs = make_dir();
    std::ofstream(theirs + "/large_coordinates_reference.pcd") << "child";
    ::_exit(theirs == ours ? 3 : 0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "the child process got the same folder " << ours;
  EXPECT_EQ(ReadWholeFile(ours + "/large_coordinates_reference.pcd"), "parent");
}

TEST(LargeCoordinates, FreshTestDirIsPerProcess) {
  ExpectChildDoesNotTouchOurFolder([] { return FreshTestDir("tool"); });
}

TEST(LargeCoordinates, TestScratchDirIsPerProcess) {
  ExpectChildDoesNotTouchOurFolder([] { return TestScratchDir(); });
}

// Same test name as above, another suite: another folder.
TEST(OtherSuite, FreshTestDirIsPerProcess) {
  const std::string here = FreshTestDir("tool");
  EXPECT_NE(here.find("OtherSuite"), std::string::npos) << here;
}

TEST(ScratchDir, KeptWithinATestEmptiedOnItsFirstUse) {
  const std::string dir = TestScratchDir();
  EXPECT_TRUE(fs::is_empty(dir));
  std::ofstream(ScratchPath("a.txt")) << "a";
  EXPECT_EQ(TestScratchDir(), dir);
  EXPECT_EQ(ReadWholeFile(dir + "/a.txt"), "a");
}

}  // namespace
}  // namespace testing
}  // namespace mlndt
