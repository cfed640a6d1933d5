#include "lab/experiments/paper_axes.h"

#include <cmath>

#include "mlndt/common/pose.h"

namespace mlndt {
namespace experiments {

const char* PaperAxisLabel(int axis) {
  static const char* const kLabels[] = {
      "tx [cm]", "ty [cm]", "tz [cm]", "α [deg]", "β [deg]", "γ [deg]"};
  return axis >= 0 && axis < 6 ? kLabels[axis] : "?";
}

Vector6d PaperAxesError(const Isometry3d& reference,
                        const Isometry3d& estimate) {
  const Vector6d d =
      IsometryToPoseVector(estimate) - IsometryToPoseVector(reference);
  Vector6d ours = d;
  for (int i = 3; i < 6; ++i) {
    ours(i) = std::remainder(d(i), 2.0 * M_PI);  // Wrap the angle.
  }
  Vector6d paper;
  paper << -100.0 * ours(1), 100.0 * ours(2), 100.0 * ours(0),
      -ours(4) * kRadToDeg, ours(5) * kRadToDeg, ours(3) * kRadToDeg;
  return paper;
}

ColumnStats ComputeColumnStats(const std::vector<double>& values) {
  ColumnStats s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0.0, sum_abs = 0.0, max_abs = 0.0;
  for (const double v : values) {
    sum += v;
    sum_abs += std::abs(v);
    max_abs = std::max(max_abs, std::abs(v));
  }
  s.mean = sum / values.size();
  s.mean_abs = sum_abs / values.size();
  s.max_abs = max_abs;
  double sq = 0.0;
  for (const double v : values) sq += (v - s.mean) * (v - s.mean);
  s.std = values.size() > 1 ? std::sqrt(sq / (values.size() - 1)) : 0.0;
  return s;
}

}  // namespace experiments
}  // namespace mlndt
