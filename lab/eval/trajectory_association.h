#pragma once

// Pairing the poses of an estimated trajectory with those of a reference
// trajectory that describe the same instant, before comparing them
// (trajectory_metrics.h, kitti_segment_errors.h).

#include <cstddef>
#include <vector>

#include "lab/eval/trajectory.h"
#include "mlndt/common/types.h"

namespace mlndt {

// Pair k is reference.world_from_sensor(reference_indices[k]) and
// estimate.world_from_sensor(estimate_indices[k]), copied into `reference`
// and `estimate`. Pairs are in time order; both index lists increase
// strictly.
struct AssociatedPoses {
  std::vector<size_t> reference_indices;
  std::vector<size_t> estimate_indices;
  std::vector<Isometry3d> reference;  // world_from_sensor of the reference.
  std::vector<Isometry3d> estimate;   // world_from_sensor of the estimate.

  size_t size() const { return reference.size(); }
};

// Pairs pose k of both for k < min(reference.size(), estimate.size()): the
// KITTI convention, where the line index is the frame.
AssociatedPoses AssociateByIndex(const Trajectory& reference,
                                 const Trajectory& estimate);

// Pairs each estimate pose with the reference pose nearest in time (the
// earlier one on a tie) when their timestamps differ by at most
// max_difference_s [s] (TUM files; the TUM benchmark uses 0.02 s). When
// several estimate poses have the same nearest reference pose, only the
// closest of them (the earliest on a tie) is kept, so each pose is used at
// most once and the pairs stay in time order.
AssociatedPoses AssociateByTimestamp(const Trajectory& reference,
                                     const Trajectory& estimate,
                                     double max_difference_s);

}  // namespace mlndt
