#include "tools/cli/tool_utils.h"

#include <gflags/gflags.h>
#include <sys/resource.h>

namespace mlndt {
namespace tools {

std::string CommandLine() {
  std::string line;
  for (const std::string& arg : gflags::GetArgvs()) {
    line += (line.empty() ? "" : " ") + arg;
  }
  return line;
}

double PeakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

}  // namespace tools
}  // namespace mlndt
