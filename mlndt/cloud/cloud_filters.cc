#include "mlndt/cloud/cloud_filters.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool RangeCrop::IsValid(std::string* error) const {
  MLNDT_OPTION_IN_RANGE(min_range_m, 0.0, 1e9);
  if (max_range_m != 0.0) {
    MLNDT_OPTION_GT(max_range_m, min_range_m);
    MLNDT_OPTION_LE(max_range_m, 1e9);
  }
  return true;
}

size_t CropByRange(const RangeCrop& crop, PointCloud* scan) {
  CHECK(scan != nullptr);
  std::string error;
  CHECK(crop.IsValid(&error)) << error;
  const double min_squared = crop.min_range_m * crop.min_range_m;
  const double max_squared = crop.max_range_m > 0.0
                                 ? crop.max_range_m * crop.max_range_m
                                 : std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d>* points = scan->mutable_points();
  const size_t before = points->size();
  points->erase(
      std::remove_if(points->begin(),
                     points->end(),
                     [&](const Eigen::Vector3d& p) {
                       const double r2 = p.squaredNorm();
                       // Negated so that NaN is removed too.
                       return !(r2 >= min_squared && r2 <= max_squared);
                     }),
      points->end());
  return before - points->size();
}

}  // namespace mlndt
