#pragma once

// A folder of its own for every test that writes files: ctest -j runs the
// tests in parallel, and two test programs may share a test name, so fixed
// names in ::testing::TempDir() race (issue 27, item 17).

#include <string>

namespace mlndt {
namespace testing {

// TempDir()/mlndt_<suite>_<test>_<pid>: emptied on the current test's
// first call in this process, kept on the later ones. Without a current
// test (a static initialiser), "static" stands for suite and test.
std::string TestScratchDir();

// TestScratchDir() + "/" + name.
std::string ScratchPath(const std::string& name);

}  // namespace testing
}  // namespace mlndt
