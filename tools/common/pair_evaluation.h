#pragma once

// Registering one scan pair from a ScanStore and scoring the result against
// the ground truth, plus the summary statistics the evaluation tools print
// (the layout of the paper's Tables 2-4: mean, std and max of |error|).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/pipeline/matcher.h"
#include "tools/common/scan_store.h"

namespace mlndt {
namespace tools {

// The paper's success rule (Section 5.2.1): translation error below 50 cm.
constexpr double kSuccessTranslationM = 0.5;
// A stricter rule used by the tests and the convergence experiments.
constexpr double kStrictTranslationM = 0.2;
constexpr double kStrictRotationDeg = 1.0;

// Error of an estimated relative pose (reference_from_input) against the
// ground truth. The error transform is E = truth^-1 * estimate, which maps
// the input frame as estimated into the input frame as it truly is;
// `components` is its pose vector (IsometryToPoseVector: tx, ty, tz [m],
// alpha, beta, gamma [rad]). |t(E)| equals TranslationErrorM(truth,
// estimate) and the angle of R(E) equals RotationErrorRad(truth, estimate).
struct PoseError {
  Vector6d components = Vector6d::Zero();
  double translation_m = 0.0;
  double rotation_rad = 0.0;
};

inline PoseError ComputePoseError(const Isometry3d& truth,
                                  const Isometry3d& estimate) {
  PoseError e;
  const Isometry3d error = truth.inverse() * estimate;
  e.components = IsometryToPoseVector(error);
  e.translation_m = error.translation().norm();
  e.rotation_rad = Eigen::AngleAxisd(error.linear()).angle();
  return e;
}

inline bool IsSuccess(const PoseError& e) {
  return e.translation_m < kSuccessTranslationM;
}
inline bool IsStrictSuccess(const PoseError& e) {
  return e.translation_m < kStrictTranslationM &&
         e.rotation_rad * kRadToDeg < kStrictRotationDeg;
}

// Scales a relative motion by c: the translation by c and the rotation's
// axis-angle by c (the paper's initialisation Z_i = c Z_gt, Table 9).
inline Isometry3d ScaleMotion(const Isometry3d& motion, double c) {
  const Eigen::AngleAxisd rotation(motion.linear());
  Isometry3d scaled = Isometry3d::Identity();
  scaled.linear() = Eigen::AngleAxisd(c * rotation.angle(), rotation.axis())
                        .toRotationMatrix();
  scaled.translation() = c * motion.translation();
  return scaled;
}

// Summary statistics of a list of numbers. std is the sample standard
// deviation (n - 1; 0 for n < 2); median is the middle value or the mean of
// the two middle values; p95 is the nearest-rank 95th percentile, the value
// at sorted index ceil(0.95 n) - 1. All zero for an empty list.
struct Stats {
  size_t count = 0;
  double mean = 0.0;
  double std = 0.0;
  double min = 0.0;
  double max = 0.0;
  double median = 0.0;
  double p95 = 0.0;
};

inline Stats ComputeStats(std::vector<double> values) {
  Stats s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / values.size();
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = values.size() > 1 ? std::sqrt(squares / (values.size() - 1)) : 0.0;
  s.min = values.front();
  s.max = values.back();
  const size_t n = values.size();
  s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * n));
  s.p95 = values[std::max<size_t>(rank, 1) - 1];
  return s;
}

// Wall times of one pair [ms]. total = map + the registration's own total
// (sampling + solve + bookkeeping).
struct PairTimes {
  double total_ms = 0.0;
  double map_ms =
      0.0;  // Building the reference map for this pair; 0 when reused.
  double sampling_ms = 0.0;
  double solve_ms = 0.0;
};

// Registers scan `input` onto scan `reference` with the chosen method, on
// the store's map of the reference (built once, reused afterwards). False
// with *error only when a scan cannot be read or its map cannot be built; a
// registration FAILURE is reported in *summary.
inline bool RegisterPair(const MatcherOptions& options,
                         ScanStore* store,
                         size_t reference,
                         size_t input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary,
                         PairTimes* times,
                         std::string* error) {
  *summary = RegistrationSummary();
  *times = PairTimes();
  const PointCloud* input_cloud = store->Cloud(input, error);
  if (input_cloud == nullptr) return false;
  const PointCloud* reference_cloud = store->Cloud(reference, error);
  if (reference_cloud == nullptr) return false;
  LayeredGridOptions grid_options;
  if (!MatcherGridOptions(options, *reference_cloud, &grid_options, error)) {
    *error = store->path(reference) + ": map: " + *error;
    return false;
  }
  double build_time_s = 0.0;
  const LayeredGrid* map =
      store->Map(reference, grid_options, &build_time_s, error);
  if (map == nullptr) return false;
  RegisterWithMatcher(
      options, *map, *input_cloud, initial_reference_from_input, summary);
  times->map_ms = build_time_s * 1e3;
  times->total_ms = (build_time_s + summary->total_time_s) * 1e3;
  times->sampling_ms = summary->sampling_time_s * 1e3;
  times->solve_ms = summary->solve_time_s * 1e3;
  return true;
}

}  // namespace tools
}  // namespace mlndt
