#pragma once

// mlndt_odometry's errors against a reference of one world_from_sensor pose
// per scan: the ATE after an SE(3) alignment, the RPE over `rpe_delta` scans
// and the KITTI devkit's segment errors (lab/eval/trajectory_metrics.h,
// kitti_segment_errors.h), both trajectories taken from the first scan.

#include <string>
#include <vector>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/trajectory_metrics.h"
#include "mlndt/odometry/odometry.h"

namespace mlndt {

struct OdometryMetrics {
  AteSummary ate;
  // The RPE's scans between the two poses of a motion: as asked, but at
  // most results.size() - 1 (an 8-scan run's RPE is over 7 scans).
  int rpe_delta = 1;
  int rpe_delta_asked = 1;
  RpeSummary rpe;
  KittiSegmentSummary segments;
};

// The errors of results[k].world_from_sensor against reference[k] (the
// reference re-based on its first pose: the odometry's frame is the first
// scan's), segments every frame over `lengths_m`. False with *error when
// there are no results, fewer reference poses than results, or a metric
// refuses its input (too few poses for the alignment, invalid lengths).
bool ComputeOdometryMetrics(const std::vector<Isometry3d>& reference,
                            const std::vector<OdometryResult>& results,
                            int rpe_delta,
                            const std::vector<double>& lengths_m,
                            OdometryMetrics* metrics,
                            std::string* error);

}  // namespace mlndt
