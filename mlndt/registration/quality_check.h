#pragma once

// The verdict of a registration: whether its pose can be trusted. A solver
// stopping on a small step says nothing about whether it stopped at the
// right pose; the fit of the input to the map at the solution does. Two
// checks, on the last layer:
//  - fit (FitQuality, cost/fit_quality.h): enough inliers under a
//    Mahalanobis gate and a low enough score per matched point; a wrong
//    pose leaves most points far from their cells (docs/trust.md shows the
//    measures of right and wrong results on the shared suite, and how the
//    thresholds were chosen);
//  - constraint: the Gauss-Newton Hessian, with rotations scaled to metres
//    at the points' RMS range, constrains every direction; a plane or a
//    corridor leaves directions along which the pose slides.

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/fit_quality.h"

namespace mlndt {

struct QualityCheckOptions {
  // Off: the solver's termination is reported as it is.
  bool enabled = true;
  // Mahalanobis distance below which a point is an inlier. In [0.5, 10].
  double inlier_gate = 3.0;
  // LOW_QUALITY below this share of inliers among the sampled points. In
  // [0, 1].
  double min_inlier_fraction = 0.25;
  // LOW_QUALITY above this mean score per matched point. In (0, 1e6].
  double max_mean_score = 11.0;
  // DEGENERATE when the weakest direction of the scaled Hessian carries less
  // than this fraction of the strongest one's information. In [0, 1).
  double min_constraint_ratio = 1e-3;

  bool IsValid(std::string* error) const;
};

// How well the pose is constrained (from the Hessian at the solution).
struct ConstraintAnalysis {
  // lambda_min / lambda_max of S H S, S = diag(1, 1, 1, 1/L, 1/L, 1/L) with
  // L the RMS range of the input points: 1 for an isotropic fit, 0 for a
  // direction with no information.
  double constraint_ratio = 0.0;
  // Unit directions of the pose vector (tx, ty, tz, alpha, beta, gamma;
  // angles scaled as above) whose ratio is below the threshold.
  std::vector<Vector6d> degenerate_directions;
};

// Analyses `hessian` (d2 score / d xi2) for input points of RMS range
// `rms_range_m` (> 0).
ConstraintAnalysis AnalyseConstraints(const Matrix6d& hessian,
                                      double rms_range_m,
                                      double min_constraint_ratio);

// CONVERGENCE/NO_CONVERGENCE stay when both checks pass; otherwise
// LOW_QUALITY or DEGENERATE, with the reason in *message.
TerminationType CheckQuality(const QualityCheckOptions& options,
                             TerminationType solver_termination,
                             const FitQuality& fit,
                             const ConstraintAnalysis& constraints,
                             std::string* message);

// "translation along (0.98, 0.17, 0.00)" and the like, for messages.
std::string DescribeDirection(const Vector6d& direction);

}  // namespace mlndt
