#pragma once

// The odometry over a whole sequence: loads each scan when its turn comes
// and runs Odometry::Process on it (odometry.h), so only the current scan
// and the local map are held.

#include <functional>
#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/progress.h"
#include "mlndt/odometry/odometry.h"

namespace mlndt {

// Loads scan `index`: its points (sensor frame), its per-point times
// relative to its stamp (cleared when it has none) and its stamp [s].
using OdometryScanLoader =
    std::function<bool(size_t index,
                       PointCloud* cloud,
                       std::vector<double>* point_times_s,
                       double* stamp_s,
                       std::string* error)>;

// Runs scans 0..num_scans-1, replacing the pose of each scan a later one
// bridged by the interpolated one (and setting its `interpolated`).
// `progress` (may be null, not owned) hears of each scan once it is
// processed: its verdict, start layer, prediction uncertainty and time. False
// with *error on invalid options, a scan that cannot be loaded or is unusable
// input (Odometry::Process); the results so far are kept in *results.
bool RunOdometry(const OdometryOptions& options,
                 size_t num_scans,
                 const OdometryScanLoader& load_scan,
                 ProgressCallback* progress,
                 std::vector<OdometryResult>* results,
                 OdometrySummary* summary,
                 std::string* error);

}  // namespace mlndt
