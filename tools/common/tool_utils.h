#pragma once

// Small helpers shared by the tools: number lists from flags, 4x4 matrix
// text files, peak memory. Tools write every output file with
// WriteFileAtomically (mlndt/common/atomic_file.h, included here): the text
// is built in memory, then replaces the file in one step.

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mlndt/common/atomic_file.h"
#include "mlndt/common/types.h"

namespace mlndt {
namespace tools {

// Parses "a,b,c" into numbers; false when any item is not a finite number,
// including empty items ("1,,2", a leading or a trailing comma: "1,2,").
// Spaces around a number are allowed. "" gives no numbers (callers check the
// count they need).
inline bool ParseNumberList(const std::string& text,
                            std::vector<double>* values) {
  values->clear();
  if (text.empty()) return true;
  size_t begin = 0;
  while (true) {
    const size_t comma = text.find(',', begin);
    const std::string item = text.substr(
        begin, comma == std::string::npos ? std::string::npos : comma - begin);
    if (item.find_first_not_of(" \t") == std::string::npos) return false;
    try {
      size_t used = 0;
      const double v = std::stod(item, &used);
      if (item.find_first_not_of(" \t", used) != std::string::npos) {
        return false;
      }
      if (!std::isfinite(v)) return false;
      values->push_back(v);
    } catch (...) {
      return false;
    }
    if (comma == std::string::npos) return true;
    begin = comma + 1;
  }
}

// Reads 12 or 16 whitespace-separated numbers (row-major 3x4 or 4x4).
inline bool ReadMatrixFile(const std::string& path,
                           Isometry3d* transform,
                           std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot open";
    return false;
  }
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  if (!in.eof() || (v.size() != 12 && v.size() != 16)) {
    *error =
        path + ": expected 12 or 16 numbers (a row-major 3x4 or 4x4 matrix)";
    return false;
  }
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = v[static_cast<size_t>(i)];
  transform->matrix() = m;
  return true;
}

// `value` with `precision` decimals for tables; "–" when not finite.
inline std::string Fmt(double value, int precision) {
  if (!std::isfinite(value)) return "–";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", precision, value);
  return text;
}

// The process's peak resident set size so far [bytes] (getrusage; Linux
// reports ru_maxrss in KiB).
inline double PeakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

}  // namespace tools
}  // namespace mlndt
