#pragma once

// The probe of a direction of the pose (quality_check.h's constraint test,
// and the verdict's search along the flattest direction): the pose moved by
// one cell edge along a scaled direction, both ways, and the share of the
// inliers (Mahalanobis distance below the gate; ML-NDT Eq. 10's e^T C^-1 e)
// that stay inliers. Not installed.

#include <limits>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/cost/point_matches.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {
namespace internal {

// The pose moved by `step_m` along the scaled direction d = [a; b] (a a
// translation, b a rotation times the lever `rms_range_m`, applied about the
// origin after the pose's rotation), as the probe moves it.
Isometry3d MovedAlong(const Isometry3d& pose,
                      const Vector6d& d,
                      double step_m,
                      double rms_range_m);

// How much worse the fit is one cell edge away along d, the weaker of the
// two ways: `kept`, the share of the inliers left; `evidence`, the inliers
// lost net of those gained over the square root of all that changed.
struct Probe {
  double kept = 1.0;
  double evidence = std::numeric_limits<double>::infinity();
};

// Every point matched once at the solution (point_matches.h).
std::vector<PointMatch> MatchAtSolution(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective);

// Whether each matched point is an inlier (Mahalanobis distance below
// `gate`).
std::vector<bool> InlierFlags(const std::vector<PointMatch>& matches,
                              double gate);

// The probe along d from `pose`, whose points' inlier flags are `inlier`.
Probe ProbeDirection(const NdtLayer& layer,
                     const std::vector<Eigen::Vector3d>& input_points,
                     const Isometry3d& pose,
                     const ObjectiveOptions& objective,
                     double rms_range_m,
                     double gate,
                     const std::vector<bool>& inlier,
                     const Vector6d& d);

// The probe along the scaled direction d (as MovedAlong moves the pose), one
// cell edge of `layer`, for the points moved by xi; `gate` as
// QualityCheckOptions::inlier_gate.
Probe ProbeAlong(const NdtLayer& layer,
                 const std::vector<Eigen::Vector3d>& input_points,
                 const Vector6d& reference_from_input_xi,
                 const ObjectiveOptions& objective,
                 double rms_range_m,
                 double gate,
                 const Vector6d& d);

}  // namespace internal
}  // namespace mlndt
