#pragma once

// Drops the returns of a raw scan that are not measurements of the scene:
// points at the sensor (a cluster at about 0.1 m on the 3DTK and PCL room
// scans, at the origin itself on the koide3 pair) and a scanner's "no
// return" value at its maximum range (3DTK: 32.77 m). Both travel with the
// sensor, so left in they pin a registration to zero motion. Ranges are
// distances from the cloud's origin: apply it to scans in their sensor
// frame, not to maps merged in a world frame.

#include <cstddef>
#include <string>

#include "mlndt/cloud/point_cloud.h"

namespace mlndt {

class OptionTable;

struct RangeFilterOptions {
  // Points closer than this to the sensor are dropped [m]. In [0, 1e3].
  double min_range_m = 0.25;
  // Points farther than this are dropped [m]; 0 keeps every range. 0, or
  // in [min_range_m, 1e6].
  double max_range_m = 0.0;
  // Points within 1 cm of the cloud's largest range are dropped when they
  // are at least this fraction of the cloud (a saturated maximum range; a
  // real scan has a handful of points there). 0 turns the rule off. In
  // [0, 1].
  double saturated_range_fraction = 0.005;

  bool IsValid(std::string* error) const;
};

// RangeFilterOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& RangeFilterOptionsTable();

struct RangeFilterSummary {
  size_t input_points = 0;
  size_t kept_points = 0;
  size_t too_close = 0;
  size_t too_far = 0;
  size_t saturated = 0;  // At the saturated maximum range.
};

// What dropped the points, filter by filter, e.g. "5000 at the cloud's
// largest range (saturated_range_fraction 0.005: a saturated range, or
// every point at one distance)"; the filters that dropped none are left out.
std::string DescribeDroppedPoints(const RangeFilterOptions& options,
                                  const RangeFilterSummary& summary);

// The points of `cloud` the options keep, in input order. Options must be
// valid (CHECKed).
PointCloud FilterByRange(const RangeFilterOptions& options,
                         const PointCloud& cloud,
                         RangeFilterSummary* summary);

// As FilterByRange, into *kept (its points are replaced). Its memory is
// reused when its capacity holds all of `cloud`: a caller that filters cloud
// after cloud into one buffer touches no fresh memory pages for it (a first
// touch costs ~10-15 us a page on a KVM guest: docs/performance.md).
void FilterByRange(const RangeFilterOptions& options,
                   const PointCloud& cloud,
                   PointCloud* kept,
                   RangeFilterSummary* summary);

}  // namespace mlndt
