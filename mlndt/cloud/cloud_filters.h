#pragma once

// Filters a scan goes through before it becomes part of a map: a crop by
// range from the sensor. (Voxel-grid downsampling is VoxelDownsample in
// sampling/point_sampler.h.)

#include <cstddef>
#include <string>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

// Which ranges |p| [m] from the sensor (the origin of the scan's own frame)
// are kept: min_range_m <= |p| <= max_range_m, no upper limit when
// max_range_m is 0.
struct RangeCrop {
  double min_range_m = 0.0;  // >= 0, finite.
  double max_range_m = 0.0;  // 0 (no limit), or finite and > min_range_m.

  bool IsValid(std::string* error) const;
  // True when every finite point is kept (both limits off).
  bool IsIdentity() const { return min_range_m == 0.0 && max_range_m == 0.0; }
};

// Removes, in place and keeping the order of the rest, the points of a scan
// in its sensor frame outside `crop` (and non-finite points); returns how
// many were removed. CHECK-fails on an invalid crop.
size_t CropByRange(const RangeCrop& crop, PointCloud* scan);

}  // namespace mlndt
