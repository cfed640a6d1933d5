#include "mlndt/cloud/range_filter.h"

#include <glog/logging.h>

#include <algorithm>
#include <vector>

#include "mlndt/common/internal/check_option.h"

namespace mlndt {
namespace {

// Returns within this of the largest range count as "at" it [m].
constexpr double kSaturationBand = 0.01;

}  // namespace

bool RangeFilterOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_IN_RANGE(min_range_m, 0.0, 1e3);
  if (max_range_m != 0.0) MLNDT_OPTION_IN_RANGE(max_range_m, min_range_m, 1e6);
  MLNDT_OPTION_IN_RANGE(saturated_range_fraction, 0.0, 1.0);
  return true;
}

PointCloud FilterByRange(const RangeFilterOptions& options,
                         const PointCloud& cloud,
                         RangeFilterSummary* summary) {
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  RangeFilterSummary counts;
  counts.input_points = cloud.size();
  std::vector<double> ranges(cloud.size());
  double largest = 0.0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    ranges[i] = cloud[i].norm();
    largest = std::max(largest, ranges[i]);
  }
  const size_t at_largest = static_cast<size_t>(
      std::count_if(ranges.begin(), ranges.end(), [&](double r) {
        return r >= largest - kSaturationBand;
      }));
  const bool saturated =
      options.saturated_range_fraction > 0.0 &&
      static_cast<double>(at_largest) >=
          options.saturated_range_fraction * static_cast<double>(cloud.size());
  PointCloud kept;
  kept.Reserve(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    const double r = ranges[i];
    if (r < options.min_range_m) {
      ++counts.too_close;
    } else if (options.max_range_m > 0.0 && r > options.max_range_m) {
      ++counts.too_far;
    } else if (saturated && r >= largest - kSaturationBand) {
      ++counts.saturated;
    } else {
      kept.Add(cloud[i]);
    }
  }
  counts.kept_points = kept.size();
  if (summary != nullptr) *summary = counts;
  return kept;
}

}  // namespace mlndt
