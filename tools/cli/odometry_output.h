#pragma once

// What mlndt_odometry writes: the trajectories (KITTI, and TUM stamped with
// the scans' times), scans.csv and scans.json (one row per scan, from its
// result table), the trajectory metrics against a reference
// (lab/eval/odometry_metrics.h), and the top-view plot.

#include <string>
#include <vector>

#include "lab/eval/odometry_metrics.h"
#include "mlndt/odometry/odometry.h"
#include "tools/cli/json_output.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// trajectory_kitti.txt, trajectory_tum.txt (header: where the stamps come
// from), scans.csv and scans.json (OdometryResultTable, the scan's name in
// `file`) in `dir`.
bool WriteOdometryFiles(const std::string& dir,
                        const ScanInput& input,
                        const std::vector<OdometryResult>& results,
                        std::string* error);

// summary.json: verdict counts, times per scan and, when given, metrics.
Json OdometrySummaryJson(const OdometrySummary& summary,
                         const std::vector<OdometryResult>& results,
                         const OdometryMetrics* metrics);

// The verdict counts, times and metrics as text lines.
void PrintOdometrySummary(const OdometrySummary& summary,
                          const std::vector<OdometryResult>& results,
                          const OdometryMetrics* metrics);

// trajectory_xy.png: the estimate (fallbacks marked) and the reference.
bool WriteOdometryPlot(const std::string& gnuplot,
                       const std::string& dir,
                       const std::vector<OdometryResult>& results,
                       const std::vector<Isometry3d>& reference,
                       std::string* error);

}  // namespace tools
}  // namespace mlndt
