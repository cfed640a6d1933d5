// Plain-text .xyz / .txt reading (format documented in mlndt/cloud/io.h):
// one point per line, at least three numbers separated by whitespace and/or
// commas, metres; extra columns ignored; blank and '#' lines skipped.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"

namespace mlndt {
namespace internal {

bool ParseXyzText(const std::string& data,
                  std::vector<Eigen::Vector3d>* points,
                  std::string* error) {
  points->reserve(std::count(data.begin(), data.end(), '\n') + 1);
  LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    line = Trim(line);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> tokens =
        SplitTokens(line, /*commas=*/true);
    Eigen::Vector3d point;
    bool ok = tokens.size() >= 3;
    for (int axis = 0; ok && axis < 3; ++axis) {
      ok = ParseDouble(tokens[axis], &point[axis]);
    }
    if (!ok) {
      *error =
          "line " + std::to_string(cursor.line_number()) +
          ": cannot parse point, expected at least 3 numbers 'x y z', found '" +
          std::string(line.substr(0, 60)) + "'";
      return false;
    }
    points->push_back(point);
  }
  if (points->empty()) {
    *error = data.empty() ? "empty file: no points"
                          : "no points (only blank or '#' comment lines)";
    return false;
  }
  return true;
}

}  // namespace internal
}  // namespace mlndt
