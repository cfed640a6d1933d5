#pragma once

// Runs a built tool from a test and captures its exit code, stdout and
// stderr. stderr goes to a file named after the current test, so ctest can
// run tests in parallel.

#include <string>
#include <vector>

namespace mlndt {
namespace testing {

struct ToolRun {
  int exit_code = -1;
  std::string out;                 // stdout.
  std::vector<std::string> lines;  // stdout, its non-empty lines.
  std::string err;                 // stderr.
};

// Single-quotes `text` for /bin/sh.
std::string ShellQuote(const std::string& text);

// The whole file, or "" when it cannot be read.
std::string ReadWholeFile(const std::string& path);

// A fresh, empty folder for the current test, of its own per test and per
// process (ctest -j runs tests in parallel, and two test programs may
// share a test name): TempDir()/<tool>_test_<suite>_<test name>_<pid>,
// removed first if it exists.
std::string FreshTestDir(const std::string& tool);

// Runs the tool `name` (ToolPath) with `args`, already quoted where needed.
// With timeout_s > 0 the tool is killed after that many seconds (exit code
// 124, as timeout(1) reports it).
ToolRun RunTool(const std::string& name,
                const std::string& args,
                int timeout_s = 0);

}  // namespace testing
}  // namespace mlndt
