#pragma once

// The verdict of a registration: whether its pose can be trusted. A solver
// stopping on a small step says nothing about whether it stopped at the
// right pose; the fit of the input to the map at the solution does. Two
// checks, on the last layer:
//  - fit (FitQuality, cost/fit_quality.h): the matched points' median
//    Mahalanobis distance to their cells, and some overlap; a wrong pose
//    leaves most points far from their cells (docs/trust.md shows the
//    measures of right and wrong results on the shared suite, and how the
//    thresholds were chosen);
//  - constraint: the surfaces the points lie on constrain every direction of
//    the pose. Each matched point's cell contributes the directions it is
//    thin in (its plane's normal, or the two across a line) as rows
//    [v; (R p) x v / L] (point-to-plane, with rotations scaled to metres at
//    the points' RMS range L); the Hessian itself does not tell, since the
//    covariance regularisation gives every cell some in-plane information.
//    Whether a direction is free is decided on planar cells alone: where a
//    spinning LiDAR's rings are farther apart than a cell, one ring crosses
//    it, and the gap between rings looks like a surface although it is the
//    sensor's pattern, which pulls two scans to where their rings coincide
//    (no motion); a line cell's two thin directions cannot be told apart.
//    A plane leaves its in-plane translations and the turn about its normal
//    free, a corridor its length. The eigenvalue ratio alone depends on the
//    point count (sparse cells have spurious thin directions), so the weak
//    directions (of all the rows, line cells included) are also probed: the
//    pose is moved by one cell edge along each, both ways; when almost all
//    inliers stay inliers (a share, not a count, so that the answer does not
//    depend on the density) and the few lost are not clearly more than those
//    gained, the data cannot tell the poses apart (a flat direction). A weak
//    but real constraint (a street's cross walls) loses the points on the
//    surfaces across it (ProbeDirection in
//    registration/internal/direction_probe.h).
//  - localizability (localizability.h): the share of the inliers on planar
//    cells whose normal constrains each direction of the pose; a direction
//    that almost none constrain is free (min_localizability).

#include <limits>
#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/fit_quality.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class OptionTable;
class ResultTable;

struct QualityCheckOptions {
  // Off: the solver's termination is reported as it is.
  bool enabled = true;
  // Mahalanobis distance below which a point is an inlier. In [0.5, 10].
  double inlier_gate = 3.0;
  // LOW_QUALITY above this median Mahalanobis distance of the matched
  // points (sqrt of Eq. 10's e^T C^-1 e): the bulk of a right fit sits within
  // a few sigma of its cells whatever the sensor, while a wrong pose moves
  // most points off their surfaces. A median, so that the points outside the
  // overlap do not count: the share of those depends on the scene and the
  // sensor's field of view, not on the pose (docs/trust.md). In (0, 100].
  double max_median_distance = 3.8;
  // LOW_QUALITY below this share of inliers among the sampled points: too
  // little overlap to judge the fit. In [0, 1].
  double min_inlier_fraction = 0.1;
  // LOW_QUALITY above this mean score per matched point. In (0, 1e6]; the
  // default 1e6 is off (the mean counts the points outside the overlap).
  double max_mean_score = 1e6;
  // DEGENERATE when the weakest direction of the pose gets less than this
  // fraction of the strongest one's constraint (ConstraintAnalysis). In
  // [0, 1).
  double min_constraint_ratio = 0.01;
  // DEGENERATE when fewer than this share of the inliers on planar cells
  // constrain a direction of the pose through their normal
  // (Localizability, localizability.h): the surfaces the points lie on
  // leave that direction free (a corridor's axis, a wall's plane), whatever
  // the point density. Judged on the chosen minimum, after the searches
  // for it (attempts.h, step 6). In [0, 1); 0 = off.
  double min_localizability = 0.02;
  // DEGENERATE when moving the pose by one last-layer cell edge along one of
  // its weak directions keeps more than `max_flatness` of the inliers both
  // ways, and the net loss is below `min_probe_evidence` standard deviations
  // of the points that change (ConstraintAnalysis). max_flatness in (0, 1],
  // 1 = off. Density-independent: a free direction keeps all its inliers up
  // to noise, a weak but real one loses the points on the surfaces across
  // it (a street's cross walls; docs/trust.md gives the measured shares).
  // min_probe_evidence >= 0.
  double max_flatness = 0.95;
  double min_probe_evidence = 12.0;

  // LOW_QUALITY when fewer input points than this were sampled: too few
  // to tell a right fit from a wrong one (docs/trust.md). In [0, 1e6].
  int min_fit_points = 500;

  bool IsValid(std::string* error) const;
};

// QualityCheckOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& QualityCheckOptionsTable();

// How well the pose is constrained at a solution.
struct ConstraintAnalysis {
  // lambda_min / lambda_max of the sum of the planar cells' rows above: 1
  // when every direction is constrained alike, 0 for a direction with no
  // information.
  double constraint_ratio = 0.0;
  // The smallest share of the inliers on planar cells that constrain a
  // direction of the pose (Localizability::share; localizability.h): 0
  // along a free direction, about 1/6 or more in a well-conditioned scene.
  double localizability = 0.0;
  // That direction (unit, scaled as the rows above).
  Vector6d least_localizable_direction = Vector6d::Zero();
  // How many of degenerate_directions are below min_localizability.
  int unlocalizable_directions = 0;
  // Unit directions (translation [m]; rotation vector scaled by L) whose
  // eigenvalue is below min_constraint_ratio times the largest.
  std::vector<Vector6d> degenerate_directions;
  // The largest share of inliers kept when the pose moves one cell edge
  // along a weak direction (the worse of the two ways): near 1 along a free
  // direction, small along a constrained one; 0 when nothing was probed
  // (also when the probe is off, max_flatness = 1).
  double flatness = 0.0;
  // Along the flattest direction: the inliers lost net of those gained, over
  // the square root of all that changed (a z-score; near 0 when free).
  double probe_evidence = 0.0;
  // The flattest probed direction (unit, scaled as the rows above); zero
  // when nothing was probed.
  Vector6d flattest_direction = Vector6d::Zero();
  // How many of degenerate_directions were found flat by the probe.
  int flat_directions = 0;
  // The translations the planar cells constrain least with the rotation
  // held: the eigenvectors of the translation block of their rows' sum,
  // weakest first (columns; zero when no cell matched).
  Matrix3d weakest_translations = Matrix3d::Zero();
};

// ConstraintAnalysis's fields: name, unit, help (result_table.h).
const ResultTable& ConstraintAnalysisTable();

// Analyses the fit of `input_points` moved by xi onto `layer` (cells as the
// objective's policy matches them); rotations about the input points' own
// origin, scaled by `rms_range_m` (> 0). Directions are degenerate by
// options.min_constraint_ratio or, probed, when flat (QualityCheckOptions).
ConstraintAnalysis AnalyseConstraints(
    const NdtLayer& layer,
    const std::vector<Eigen::Vector3d>& input_points,
    const Vector6d& reference_from_input_xi,
    const ObjectiveOptions& objective,
    double rms_range_m,
    const QualityCheckOptions& options);

// CONVERGENCE/NO_CONVERGENCE stay when both checks pass; otherwise
// LOW_QUALITY or DEGENERATE, with the reason in *message.
TerminationType CheckQuality(const QualityCheckOptions& options,
                             TerminationType solver_termination,
                             const FitQuality& fit,
                             const ConstraintAnalysis& constraints,
                             std::string* message);

// A solution judged: its fit, its constraints and the verdict on them.
struct Judgement {
  FitQuality fit;
  ConstraintAnalysis constraints;
  TerminationType verdict = TerminationType::FAILURE;
  std::string message;  // Why, when the verdict is not the solver's.
};

// The one verdict of a pose, whichever method found it (ML-NDT's attempts,
// the NDT baseline): the fit of `input_points` moved by xi onto `layer`,
// the constraint analysis (rotations about the points' origin, scaled by
// `rms_range_m`) and CheckQuality on them.
Judgement JudgeSolution(const QualityCheckOptions& options,
                        TerminationType solver_termination,
                        const NdtLayer& layer,
                        const std::vector<Eigen::Vector3d>& input_points,
                        const Vector6d& reference_from_input_xi,
                        const ObjectiveOptions& objective,
                        double rms_range_m);

// The Laplace covariance `scale` H^-1 at a solution (scale 2 for whitened
// residuals of unit variance, 1 for a negative log-likelihood), infinite
// along the constraint analysis' degenerate directions and along directions
// in which H is not positive definite; the inverse on the rest.
Matrix6d LaplaceCovariance(const Matrix6d& hessian,
                           double scale,
                           const ConstraintAnalysis& constraints);

// "translation along (0.98, 0.17, 0.00)" and the like, for messages.
std::string DescribeDirection(const Vector6d& direction);

}  // namespace mlndt
