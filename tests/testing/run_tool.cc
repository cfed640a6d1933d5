#include "tests/testing/run_tool.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/testing/test_data.h"

namespace mlndt {
namespace testing {

std::string ShellQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string ReadWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

ToolRun RunTool(const std::string& name,
                const std::string& args,
                int timeout_s) {
  const ::testing::TestInfo* test =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string err_path = ::testing::TempDir() + name + "_" +
                               test->test_suite_name() + "_" + test->name() +
                               "_" + std::to_string(::getpid()) + ".stderr";
  const std::string timeout =
      timeout_s > 0 ? "timeout -k 5 " + std::to_string(timeout_s) + " " : "";
  const std::string command = timeout + ShellQuote(ToolPath(name)) + " " +
                              args + " 2>" + ShellQuote(err_path);
  ToolRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "popen failed: " << command;
    return run;
  }
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0)
    run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::istringstream stream(run.out);
  std::string line;
  while (std::getline(stream, line)) {
    if (!line.empty()) run.lines.push_back(line);
  }
  run.err = ReadWholeFile(err_path);
  return run;
}

std::string FreshTestDir(const std::string& tool) {
  const ::testing::TestInfo* test =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir = ::testing::TempDir() + tool + "_test_" +
                          test->test_suite_name() + "_" + test->name() + "_" +
                          std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace testing
}  // namespace mlndt
