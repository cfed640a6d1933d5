#include "mlndt/cloud/range_filter.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "mlndt/cloud/internal/squared_range.h"
#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"

namespace mlndt {
namespace {

// Returns within this of the largest range count as "at" it [m].
constexpr double kSaturationBand = 0.01;

// A cloud whose centroid is farther from its origin than this many RMS
// radii (and kFarOriginMinDistance) is not in a sensor frame: a scan
// surrounds its sensor (or, for a forward-looking one, lies about one
// radius ahead of it).
constexpr double kFarOriginRadii = 3.0;
constexpr double kFarOriginMinDistance = 10.0;  // [m]

bool AnyFilterOn(const RangeFilterOptions& options) {
  return options.min_range_m > 0.0 || options.max_range_m > 0.0 ||
         options.saturated_range_fraction > 0.0;
}

// Warns when the filters are on and `cloud` looks like a map-frame cloud:
// they measure ranges from its origin, which is not a sensor there.
void WarnWhenOriginIsFar(const RangeFilterOptions& options,
                         const PointCloud& cloud) {
  if (cloud.empty() || !AnyFilterOn(options)) return;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < cloud.size(); ++i) centroid += cloud[i];
  centroid /= static_cast<double>(cloud.size());
  const double distance = centroid.norm();
  // The radius only matters beyond kFarOriginMinDistance: skip its pass.
  if (distance <= kFarOriginMinDistance) return;
  double squared_radius = 0.0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    squared_radius += (cloud[i] - centroid).squaredNorm();
  }
  const double radius =
      std::sqrt(squared_radius / static_cast<double>(cloud.size()));
  if (distance <= std::max(kFarOriginMinDistance, kFarOriginRadii * radius)) {
    return;
  }
  LOG_FIRST_N(WARNING, 3)
      << "range filter: the cloud's centroid is " << distance
      << " m from its origin (its RMS radius is " << radius
      << " m): it does not look like a scan in its sensor frame, and the "
         "range filters (min_range_m, max_range_m, saturated_range_fraction) "
         "measure distances from the origin. For a map-frame cloud turn them "
         "off (min_range_m = 0, saturated_range_fraction = 0)";
}

}  // namespace

const OptionTable& RangeFilterOptionsTable() {
  using S = RangeFilterOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("RangeFilterOptions")
          .Double("min_range_m",
                  &S::min_range_m,
                  "m",
                  Closed(0.0, 1e3),
                  "Points closer than this to the cloud's origin are dropped. "
                  "The range filters measure from the origin: the sensor for "
                  "a scan in its sensor frame; for a map-frame (e.g. UTM) "
                  "cloud set min_range_m = 0 and saturated_range_fraction = "
                  "0.")
          .Double("max_range_m",
                  &S::max_range_m,
                  "m",
                  {0.0, 1e6, true, false, true},
                  "Points farther than this from the cloud's origin are "
                  "dropped; 0 keeps every range (else >= min_range_m).")
          .Double("saturated_range_fraction",
                  &S::saturated_range_fraction,
                  "",
                  Closed(0.0, 1.0),
                  "Points at the largest range are dropped when at least this "
                  "fraction of the cloud is there; 0 = off (0 for a map-frame "
                  "cloud).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool RangeFilterOptions::IsValid(std::string* error) const {
  if (!RangeFilterOptionsTable().Check(*this, error)) return false;
  if (max_range_m != 0.0) MLNDT_OPTION_IN_RANGE(max_range_m, min_range_m, 1e6);
  return true;
}

std::string DescribeDroppedPoints(const RangeFilterOptions& options,
                                  const RangeFilterSummary& summary) {
  std::ostringstream out;
  const char* separator = "";
  if (summary.too_close > 0) {
    out << summary.too_close << " closer than min_range_m "
        << options.min_range_m << " to the cloud's origin";
    separator = ", ";
  }
  if (summary.too_far > 0) {
    out << separator << summary.too_far << " farther than max_range_m "
        << options.max_range_m << " from the cloud's origin";
    separator = ", ";
  }
  if (summary.saturated > 0) {
    out << separator << summary.saturated
        << " at the cloud's largest range (saturated_range_fraction "
        << options.saturated_range_fraction
        << ": a saturated maximum range, or every point at one distance "
           "from the origin)";
  }
  return out.str();
}

PointCloud FilterByRange(const RangeFilterOptions& options,
                         const PointCloud& cloud,
                         RangeFilterSummary* summary) {
  PointCloud kept;
  FilterByRange(options, cloud, &kept, summary);
  return kept;
}

void FilterByRange(const RangeFilterOptions& options,
                   const PointCloud& cloud,
                   PointCloud* kept,
                   RangeFilterSummary* summary) {
  CHECK(kept != nullptr && kept != &cloud);
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  WarnWhenOriginIsFar(options, cloud);
  RangeFilterSummary counts;
  counts.input_points = cloud.size();
  const std::vector<Eigen::Vector3d>& points = cloud.points();
  // Squared ranges against exact squared thresholds (squared_range.h): the
  // same decisions as sqrt(s) < min_range_m etc., without a sqrt per point.
  double largest_squared = 0.0;
  for (const Eigen::Vector3d& p : points) {
    largest_squared = std::max(largest_squared, p.squaredNorm());
  }
  // sqrt is monotone, so the largest range is the sqrt of the largest s.
  const double largest = std::sqrt(largest_squared);
  const double saturation_s =
      SmallestSquareWithRangeAtLeast(largest - kSaturationBand);
  bool saturated = false;
  if (options.saturated_range_fraction > 0.0) {
    const size_t at_largest = static_cast<size_t>(
        std::count_if(points.begin(), points.end(), [&](const auto& p) {
          return p.squaredNorm() >= saturation_s;
        }));
    saturated =
        static_cast<double>(at_largest) >=
        options.saturated_range_fraction * static_cast<double>(cloud.size());
  }
  const double min_s = SmallestSquareWithRangeAtLeast(options.min_range_m);
  // r > max_range_m <=> s >= the smallest s whose range exceeds it.
  const double too_far_s =
      options.max_range_m > 0.0
          ? SmallestSquareWithRangeAbove(options.max_range_m)
          : std::numeric_limits<double>::infinity();
  // A buffer that can hold every point keeps its memory (reserve() only
  // grows it).
  std::vector<Eigen::Vector3d>& out = *kept->mutable_points();
  out.clear();
  out.reserve(points.size());
  for (const Eigen::Vector3d& p : points) {
    const double s = p.squaredNorm();
    if (s < min_s) {
      ++counts.too_close;
    } else if (s >= too_far_s) {
      ++counts.too_far;
    } else if (saturated && s >= saturation_s) {
      ++counts.saturated;
    } else {
      out.push_back(p);
    }
  }
  counts.kept_points = out.size();
  if (summary != nullptr) *summary = counts;
}

}  // namespace mlndt
