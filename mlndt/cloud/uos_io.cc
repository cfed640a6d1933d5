// 3DTK "uos" .3d reading (format and frame conversion documented in
// mlndt/cloud/io.h). 3DTK's own reader is src/scanio/scan_io_uos.cc: it skips
// an optional first line of the form "<digits> x <digits>" (uosHeaderTest in
// src/scanio/helper.cc) and reads three numbers per line.

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "mlndt/cloud/internal/cloud_readers.h"
#include "mlndt/cloud/pose_io.h"

namespace mlndt {
namespace internal {
namespace {

// True for 3DTK's optional scan-size header, e.g. "1200 x 68".
bool IsUosHeader(std::string_view line) {
  const std::vector<std::string_view> tokens = SplitTokens(line);
  auto all_digits = [](std::string_view token) {
    for (char c : token) {
      if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    }
    return !token.empty();
  };
  return tokens.size() == 3 && all_digits(tokens[0]) && tokens[1] == "x" &&
         all_digits(tokens[2]);
}

}  // namespace

bool ParseUos3d(const std::string& data,
                std::vector<Eigen::Vector3d>* points,
                std::string* error) {
  points->reserve(std::count(data.begin(), data.end(), '\n') + 1);
  LineCursor cursor(data);
  std::string_view line;
  while (cursor.Next(&line)) {
    line = Trim(line);
    if (line.empty()) continue;
    if (cursor.line_number() == 1 && IsUosHeader(line)) continue;
    const std::vector<std::string_view> tokens = SplitTokens(line);
    Eigen::Vector3d point_3dtk;
    bool ok = tokens.size() >= 3;
    for (int axis = 0; ok && axis < 3; ++axis) {
      ok = ParseDouble(tokens[axis], &point_3dtk[axis]);
    }
    if (!ok) {
      *error =
          "line " + std::to_string(cursor.line_number()) +
          ": cannot parse point, expected 'x y z' in centimetres, found '" +
          std::string(line.substr(0, 60)) + "'";
      return false;
    }
    points->push_back(Convert3dtkPoint(point_3dtk));
  }
  if (points->empty()) {
    *error = data.empty() ? "empty file: no points"
                          : "no points (only blank lines or the size header)";
    return false;
  }
  return true;
}

}  // namespace internal
}  // namespace mlndt
