#pragma once

// The runs of the layer schedule (ML-NDT Table 1) one registration makes,
// and how the reported one is chosen. Each step is a named test; every
// comparison of two solutions scores the same sampled points on the last
// layer (Eq. 10 for the score, the Mahalanobis gate for the inliers). The
// history of each step and the data it was measured on are in
// lab/records/verdict.md; docs/trust.md describes the verdicts.
//  1. the schedule from the start layer (schedule.start_layer, or the layer
//     the initial guess's uncertainty needs);
//  2. CompareWithLastLayerFromGuess, when the result left the guess (beyond
//     its uncertainty when one is given, else a quarter of a last-layer
//     cell): the coarse layers can carry a guess into another basin, so the
//     last layer alone runs from the guess, and of two distinct minima the
//     better fit is kept (a good guess is never made worse);
//  3. SearchAlongFlattestDirection, when the result converged and the probe
//     (direction_probe.h) kept at least retry.weak_direction_min_flatness of
//     its inliers one cell edge along the flattest direction: a weakly
//     constrained direction holds several minima, so the last layer runs
//     from the result moved one cell edge along it, each way; a minimum
//     with clearly more inliers (InlierGainEvidence >= 1 standard
//     deviation) and no higher score replaces it, for up to
//     retry.weak_direction_rounds rounds;
//  4. CheckPatternMinimum, when the result converged with a translation
//     within retry.scan_pattern_reach_cells last-layer cells of zero: where
//     two sensors coincide a spinning LiDAR's rings fit the reference's
//     rings whatever the motion (a minimum of the sensor's pattern, not of
//     the scene). PlanarCellsReturn runs the last layer without its line
//     cells (cell_shape.h) from the result: the result stands when the
//     planar cells return to it or do not prefer where they lead, else it
//     is replaced by a clearly better minimum there or is LOW_QUALITY.
//     SearchBeyondPatternReach then looks for the scene's own minimum
//     (1 + reach) cells along the translation the planar cells constrain
//     least; one with more inliers, or that the planar cells prefer,
//     replaces the result (ReplacePatternMinimum: LOW_QUALITY when only the
//     planar cells prefer it);
//  5. until a result converges and passes the checks: the schedule again
//     from the guess turned about the input's centroid by each yaw seed
//     (retry), each checked as in 4; the best verdict wins, then the most
//     inliers;
//  6. FlagUnlocalizable: steps 1-5 judge their runs without the
//     localizability test; the chosen result is judged with it
//     (quality_check.min_localizability): DEGENERATE when fewer than that
//     share of its inliers on planar cells constrain a translation through
//     their normal (localizability.h). Whether the surfaces pin the pose
//     down is a property of the minimum found, so it does not cut short
//     the searches for the better minimum;
//  7. FlagRivalMinimum: a converged result is DEGENERATE when a minimum any
//     of these runs converged to is distinct (more than half a last-layer
//     cell away) and fits as well (not clearly fewer inliers:
//     InlierGainEvidence >= -1); the direction to it is unbounded in the
//     covariance (rival_minima.h). A last-layer run of steps 2-4 that the
//     iteration cap stops goes on once from where it stopped;
//  8. HoldPriorAlongFreeDirections (prior_hold.h), when the initial guess
//     has a stated uncertainty: along the directions the chosen result's
//     analysis names free (steps 6-7 and the quality check's; for a
//     DEGENERATE result the localizability's as well, which steps 1-5 and
//     7 did not test), the pose
//     keeps the guess's value and the covariance the prior's; the rest is
//     minimised again with those held. The verdict stands.

#include <cstdint>
#include <memory>
#include <vector>

#include "mlndt/cost/score.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/registration/internal/input_anchor.h"
#include "mlndt/registration/registration_options.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {
namespace internal {

// What the runs need besides the options: the map, the sampled points about
// their centroid, the anchor and the backend holding the points.
struct Problem {
  const LayeredGrid& map;
  const std::vector<Eigen::Vector3d>& points;  // About the anchor.
  const InputAnchor& anchor;
  Backend* backend;
  double rms_range_m;  // Of the points about the anchor.
  const NdtLayer& last() const { return map.layer(map.num_layers()); }
  // The last layer without its line cells, built on first use (step 4).
  const NdtLayer& planar_last() const;
  mutable std::unique_ptr<NdtLayer> planar_last_;  // planar_last()'s cache.
};

// One run of the schedule, in the anchor's frame, with its assessment.
struct Attempt {
  int start_layer = 1;
  Vector6d xi_local = Vector6d::Zero();
  ScheduleSummary schedule;
  // The objective on the last layer at the solution, with its Gauss-Newton
  // Hessian: scored once, here, for the choice and the report.
  ScoreEvaluation evaluation;
  FitQuality fit;
  ConstraintAnalysis constraints;
  TerminationType verdict = TerminationType::FAILURE;  // CheckQuality's.
  std::string verdict_message;
  // Free directions kept at the prior's value (step 8; prior_hold.h), and
  // the covariance of xi_local it gives (Laplace on the rest, the prior's
  // on them); unused when 0.
  int prior_held_directions = 0;
  Matrix6d held_covariance = Matrix6d::Zero();
  bool usable() const {
    return verdict == TerminationType::CONVERGENCE ||
           verdict == TerminationType::NO_CONVERGENCE;
  }
};

// What the runs cost: how many ran, and the sampled points they evaluated
// summed over every iteration of every stage (RegistrationSummary).
struct AttemptsCost {
  int attempts = 0;
  int64_t point_iterations = 0;
};

// Runs 1-8 above.
Attempt SolveAttempts(const RegistrationOptions& options,
                      const Problem& problem,
                      const Vector6d& initial_local,
                      double start_time_s,
                      AttemptsCost* cost);

}  // namespace internal
}  // namespace mlndt
