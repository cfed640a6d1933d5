#include "mlndt/registration/internal/direction_probe.h"

#include <algorithm>
#include <cmath>

#include "mlndt/common/pose.h"
#include "mlndt/cost/transform_derivatives.h"

namespace mlndt {
namespace internal {

// Every point matched once at the solution (point_matches.h).
std::vector<PointMatch> MatchAtSolution(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective) {
  const TransformDerivatives transform(reference_from_input_xi);
  return MatchPoints(layer,
                     input_points,
                     transform.rotation(),
                     transform.translation(),
                     objective.unmatched_policy);
}

// Whether each matched point is an inlier (Mahalanobis distance below
// `gate`).
std::vector<bool> InlierFlags(const std::vector<PointMatch>& matches,
                              double gate) {
  std::vector<bool> inlier(matches.size(), false);
  for (size_t k = 0; k < matches.size(); ++k) {
    inlier[k] = matches[k].IsInlier(gate);
  }
  return inlier;
}

Probe ProbeDirection(const NdtLayer& layer,
                     const std::vector<Eigen::Vector3d>& input_points,
                     const Isometry3d& pose,
                     const ObjectiveOptions& objective,
                     double rms_range_m,
                     double gate,
                     const std::vector<bool>& inlier,
                     const Vector6d& d) {
  const double inliers = std::count(inlier.begin(), inlier.end(), true);
  Probe probe;
  for (const double sign : {1.0, -1.0}) {
    const Isometry3d moved =
        MovedAlong(pose, sign * d, layer.cell_size(), rms_range_m);
    // Streamed: the probe needs each point's flag only, not its match.
    double lost = 0.0, gained = 0.0;
    for (size_t k = 0; k < input_points.size(); ++k) {
      const Eigen::Vector3d x =
          moved.linear() * input_points[k] + moved.translation();
      const bool there =
          MatchPoint(layer, x, objective.unmatched_policy).IsInlier(gate);
      lost += inlier[k] && !there;
      gained += !inlier[k] && there;
    }
    probe.kept =
        std::min(probe.kept, 1.0 - (lost - gained) / std::max(inliers, 1.0));
    probe.evidence =
        std::min(probe.evidence,
                 (lost - gained) / std::sqrt(std::max(lost + gained, 1.0)));
  }
  return probe;
}

Isometry3d MovedAlong(const Isometry3d& pose,
                      const Vector6d& d,
                      double step_m,
                      double rms_range_m) {
  const Eigen::Vector3d omega =
      step_m * d.tail<3>() / std::max(rms_range_m, 1e-3);
  Isometry3d moved = pose;
  const double angle = omega.norm();
  if (angle > 0.0) {
    moved.linear() =
        Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() *
        pose.linear();
  }
  moved.translation() += step_m * d.head<3>();
  return moved;
}

Probe ProbeAlong(const NdtLayer& layer,
                 const std::vector<Eigen::Vector3d>& input_points,
                 const Vector6d& reference_from_input_xi,
                 const ObjectiveOptions& objective,
                 double rms_range_m,
                 double gate,
                 const Vector6d& d) {
  const std::vector<bool> inlier = InlierFlags(
      MatchAtSolution(layer, input_points, reference_from_input_xi, objective),
      gate);
  return ProbeDirection(layer,
                        input_points,
                        PoseVectorToIsometry(reference_from_input_xi),
                        objective,
                        rms_range_m,
                        gate,
                        inlier,
                        d);
}

}  // namespace internal
}  // namespace mlndt
