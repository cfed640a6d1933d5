#include "tests/testing/test_bag.h"

#include <cstdio>
#include <cstdlib>

#include "tests/testing/run_tool.h"

namespace mlndt {
namespace testing {

bool WriteTestBag(const std::string& out,
                  const std::string& topic,
                  const std::vector<std::string>& scans,
                  const std::string& options,
                  std::string* error) {
  const std::string log = out + ".log";
  std::string command =
      "/usr/bin/python3 " + ShellQuote(MLNDT_TEST_BAG_SCRIPT) + " " +
      ShellQuote(out) + " " + ShellQuote(topic) + " " + options;
  for (const std::string& scan : scans) command += " " + ShellQuote(scan);
  command += " >" + ShellQuote(log) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    *error =
        "write_test_bag.py failed (python3-rosbag and "
        "python3-sensor-msgs installed?): " +
        ReadWholeFile(log);
    return false;
  }
  std::remove(log.c_str());
  return true;
}

}  // namespace testing
}  // namespace mlndt
