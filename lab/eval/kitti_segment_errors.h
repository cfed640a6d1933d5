#pragma once

// The KITTI odometry benchmark's error measure (devkit_odometry,
// evaluate_odometry.cpp): relative pose errors over path segments of
// 100, 200, ..., 800 m, per metre travelled.
//
// For every first frame f = 0, 10, 20, ... and every length L, the last frame
// l is the first frame after f whose path distance along the reference
// exceeds that of f by more than L (PathDistancesM; the devkit's
// lastFrameFromSegmentLength); when there is none, the segment does not
// exist. With the relative motions G = reference_f^-1 reference_l and
// R = estimate_f^-1 estimate_l, the devkit's error E = R^-1 G gives
//   translation error = |t(E)| / L            [m/m; reports: x 100 = %],
//   rotation error    = angle(R(E)) / L       [rad/m; reports: deg/m].
// (E^-1 = G^-1 R has the same |t| and angle.) The devkit divides by L, not
// by the distance actually travelled, and computes in float; here double.

#include <cstddef>
#include <string>
#include <vector>

#include "mlndt/common/types.h"

namespace mlndt {

struct KittiSegmentOptions {
  std::vector<double> lengths_m = {100, 200, 300, 400, 500, 600, 700, 800};
  // A first frame every this many frames (the devkit: 10, one second).
  int first_frame_step = 10;
};

// One segment, in the devkit's own units.
struct KittiSegment {
  size_t first_frame = 0;
  size_t last_frame = 0;
  double length_m = 0.0;
  double translation_error = 0.0;  // |t(E)| / L [m/m].
  double rotation_error = 0.0;     // angle(R(E)) / L [rad/m].
};

// The mean over the segments of one length (the devkit's error plots; they
// show a length only when it has at least 3 segments).
struct KittiLengthErrors {
  double length_m = 0.0;
  size_t num_segments = 0;                 // >= 1.
  double translation_error_percent = 0.0;  // 100 x mean [m/m].
  double rotation_error_deg_per_m = 0.0;   // mean [rad/m] in deg/m.
};

struct KittiSegmentSummary {
  std::vector<KittiSegment> segments;  // By first frame, then length.
  // Only the lengths that have at least one segment, in options order: a
  // length longer than the trajectory is absent, not zero.
  std::vector<KittiLengthErrors> lengths;
  // Means over all segments, every length pooled (the devkit's stats.txt,
  // which holds them in m/m and rad/m). NaN when there is no segment.
  double translation_error_percent = 0.0;
  double rotation_error_deg_per_m = 0.0;
};

// Poses by index (frame k of both), world_from_sensor. False with *error
// when the sizes differ, there are no poses, or the options are invalid
// (a length <= 0 or given twice, first_frame_step < 1). A trajectory shorter
// than every length gives true with no segments.
bool ComputeKittiSegmentErrors(const KittiSegmentOptions& options,
                               const std::vector<Isometry3d>& reference,
                               const std::vector<Isometry3d>& estimate,
                               KittiSegmentSummary* summary,
                               std::string* error);

}  // namespace mlndt
