#pragma once

// What mlndt_odometry writes: the trajectories (KITTI, and TUM stamped with
// the scans' times), scans.csv (one row per scan with its verdict), the
// trajectory metrics against a reference, and the top-view plot.

#include <string>
#include <vector>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/trajectory_metrics.h"
#include "mlndt/odometry/odometry.h"
#include "tools/common/json_output.h"
#include "tools/common/scan_input.h"

namespace mlndt {
namespace tools {

// trajectory_kitti.txt, trajectory_tum.txt (header: where the stamps come
// from) and scans.csv in `dir`.
bool WriteOdometryFiles(const std::string& dir,
                        const ScanInput& input,
                        const std::vector<OdometryResult>& results,
                        std::string* error);

// Errors against a reference of one world_from_sensor pose per scan: ATE
// after an SE(3) alignment, RPE over `rpe_delta` scans, and the KITTI
// devkit's segment errors over `lengths_m`.
struct OdometryMetrics {
  AteSummary ate;
  int rpe_delta = 1;
  RpeSummary rpe;
  KittiSegmentSummary segments;
};

bool ComputeOdometryMetrics(const std::vector<Isometry3d>& reference,
                            const std::vector<OdometryResult>& results,
                            int rpe_delta,
                            const std::vector<double>& lengths_m,
                            OdometryMetrics* metrics,
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

// The progress line's detail of a scan: name, verdict, start layer,
// uncertainty, time.
std::string OdometryProgressDetail(const ScanInput& input,
                                   const OdometryResult& r);

// RunOdometry over the scans of `input` (stamped by it), with a progress
// line.
bool RunOdometryWithProgress(const OdometryOptions& options,
                             ScanInput* input,
                             std::vector<OdometryResult>* results,
                             OdometrySummary* summary,
                             std::string* error);

}  // namespace tools
}  // namespace mlndt
