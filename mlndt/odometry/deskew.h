#pragma once

// Motion compensation of one scan ("deskewing"): a spinning or scanning
// LiDAR takes its points over the sweep while it moves, so each point is in
// the sensor frame of its own instant. With a per-point time and the
// sensor's velocity (constant over the sweep), every point is moved into the
// frame of the scan's time stamp: p_stamp = exp(t * v) p, t the point's time
// relative to the stamp [s], v the body-frame twist per second
// (motion_prediction.h).

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"

namespace mlndt {

// Moves the points of *cloud in place; `point_times_s` holds one time per
// point, relative to the stamp. A point whose time is not finite cannot be
// placed in the stamp's frame: it is removed, and *removed (when given)
// counts such points. False with *error when the sizes differ (the cloud is
// then unchanged).
bool DeskewScan(const Vector6d& velocity,
                const std::vector<double>& point_times_s,
                PointCloud* cloud,
                std::string* error,
                size_t* removed = nullptr);

}  // namespace mlndt
