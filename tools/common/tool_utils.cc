#include "tools/common/tool_utils.h"

#include <gflags/gflags.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdio>

namespace mlndt {
namespace tools {

std::string Fmt(double value, int precision) {
  if (!std::isfinite(value)) return "–";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", precision, value);
  return text;
}

std::string Num(double value) {
  if (!std::isfinite(value)) return "nan";
  char text[64];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    out += c;
    if (c == '"') out += '"';
  }
  return out + "\"";
}

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
