#include "lab/eval/kitti_segment_errors.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lab/eval/trajectory.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

// The devkit's rotationError: acos of 0.5 (trace - 1), clamped to [-1, 1].
double RotationAngleRad(const Isometry3d& pose_error) {
  const double d = 0.5 * (pose_error.linear().trace() - 1.0);
  return std::acos(std::max(std::min(d, 1.0), -1.0));
}

bool IsValid(const KittiSegmentOptions& options, std::string* error) {
  if (options.first_frame_step < 1) {
    *error = "KITTI segment errors: first_frame_step " +
             std::to_string(options.first_frame_step) + " < 1";
    return false;
  }
  for (size_t i = 0; i < options.lengths_m.size(); ++i) {
    const double length = options.lengths_m[i];
    if (!(length > 0.0) || !std::isfinite(length)) {
      *error = "KITTI segment errors: length " + std::to_string(length) +
               " m is not a positive number";
      return false;
    }
    if (std::count(options.lengths_m.begin(),
                   options.lengths_m.begin() + i,
                   length) > 0) {
      *error = "KITTI segment errors: length " + std::to_string(length) +
               " m is given twice";
      return false;
    }
  }
  return true;
}

}  // namespace

bool ComputeKittiSegmentErrors(const KittiSegmentOptions& options,
                               const std::vector<Isometry3d>& reference,
                               const std::vector<Isometry3d>& estimate,
                               KittiSegmentSummary* summary,
                               std::string* error) {
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = KittiSegmentSummary();
  if (!IsValid(options, error)) return false;
  if (reference.size() != estimate.size() || reference.empty()) {
    *error = "KITTI segment errors: " + std::to_string(reference.size()) +
             " reference poses and " + std::to_string(estimate.size()) +
             " estimated poses (the devkit needs the same number, > 0)";
    return false;
  }
  const std::vector<double> distances = PathDistancesM(reference);
  const size_t step = static_cast<size_t>(options.first_frame_step);
  for (size_t first = 0; first < reference.size(); first += step) {
    for (double length : options.lengths_m) {
      // The first frame whose distance exceeds distances[first] + length
      // (distances never decrease, so the devkit's linear search and this
      // binary search find the same frame).
      const auto last_it = std::upper_bound(distances.begin() + first,
                                            distances.end(),
                                            distances[first] + length);
      if (last_it == distances.end()) continue;
      const size_t last = static_cast<size_t>(last_it - distances.begin());
      const Isometry3d delta_reference =
          reference[first].inverse() * reference[last];
      const Isometry3d delta_estimate =
          estimate[first].inverse() * estimate[last];
      const Isometry3d pose_error = delta_estimate.inverse() * delta_reference;
      KittiSegment segment;
      segment.first_frame = first;
      segment.last_frame = last;
      segment.length_m = length;
      segment.translation_error = pose_error.translation().norm() / length;
      segment.rotation_error = RotationAngleRad(pose_error) / length;
      summary->segments.push_back(segment);
    }
  }
  double translation_sum = 0.0, rotation_sum = 0.0;
  for (const KittiSegment& s : summary->segments) {
    translation_sum += s.translation_error;
    rotation_sum += s.rotation_error;
  }
  const double n = static_cast<double>(summary->segments.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  summary->translation_error_percent =
      summary->segments.empty() ? nan : 100.0 * translation_sum / n;
  summary->rotation_error_deg_per_m =
      summary->segments.empty() ? nan : rotation_sum / n * kRadToDeg;
  for (double length : options.lengths_m) {
    KittiLengthErrors row;
    row.length_m = length;
    double t = 0.0, r = 0.0;
    for (const KittiSegment& s : summary->segments) {
      if (s.length_m != length) continue;
      ++row.num_segments;
      t += s.translation_error;
      r += s.rotation_error;
    }
    if (row.num_segments == 0) continue;
    row.translation_error_percent = 100.0 * t / row.num_segments;
    row.rotation_error_deg_per_m = r / row.num_segments * kRadToDeg;
    summary->lengths.push_back(row);
  }
  return true;
}

}  // namespace mlndt
