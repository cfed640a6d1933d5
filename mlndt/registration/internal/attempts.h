#pragma once

// The runs of the layer schedule one registration makes (Table 1), and how
// the reported one is chosen:
//  1. the schedule from the start layer (schedule.start_layer, or the layer
//     the initial guess's uncertainty needs);
//  2. when the result left the guess (beyond its uncertainty when one is
//     given, else beyond a quarter of a last-layer cell): the last layer
//     alone from the guess, first over every s-th sample (s =
//     schedule.max_coarse_point_stride) and, only when that leads to another
//     basin, over all of them; the better fit wins, so a good guess is never
//     made worse by the coarse layers (they can pull a sparse scan into
//     another basin). Against a result where the sensors coincide (4) the
//     planar cells judge, as in 4;
//  3. when the result converged and the probe of weak directions kept at
//     least retry.weak_direction_min_flatness of its inliers one cell edge
//     along the flattest one (quality_check.h): the last layer from the
//     result moved one cell edge along that direction, each way (a subset
//     first, as in 2); a solution in another basin (within the guess's
//     uncertainty when one is given) that has clearly more inliers
//     (InlierGainEvidence >= 1 standard deviation) and no higher score
//     (Eq. 10) replaces it, and the search goes on from there for up to
//     retry.weak_direction_rounds rounds: a weakly constrained direction (a
//     road seen within a few metres, a sparse hand-held scan) holds several
//     minima, and the one the schedule found need not be the best. A
//     last-layer run of steps 2-4 that the iteration cap stops goes on once
//     from where it stopped;
//  4. the scan-pattern check, when the result converged within
//     retry.scan_pattern_reach_cells last-layer cell edges of a zero
//     translation. Where the two sensors coincide, a spinning LiDAR's rings
//     fall into the cells of the reference's own rings and fit them
//     whatever the motion: a minimum of the pattern, not of the scene (a
//     KITTI input cropped to the ground stayed at the identity, 0.7 m
//     behind). The last layer without its line cells (the single rings
//     crossing a cell; quality_check.h) runs from the result, as the layer
//     before the last runs (every 2nd sample, iterations_per_layer). When
//     it leads into another basin, the last layer runs from there as in 2:
//     a converged minimum with clearly more inliers replaces the result.
//     The result stands when the last layer returns to it and the planar
//     cells' inliers do not prefer where they led; otherwise it is
//     LOW_QUALITY. A result that stands, and whose planar cells keep as
//     many of their inliers one cell edge along the translation they
//     constrain least as the search in 3 needs, is moved (1 + reach) cell
//     edges along it, each way, and the last layer runs from there as in 2: the
//     scene's own minimum can lie beyond the pattern's (a road seen within 8 m,
//     or in a 30 deg wedge ahead, 0.7-1.5 m ahead). A converged one with more
//     inliers replaces the result (there the pattern adds inliers to the
//     result: no margin is asked), and so does one where the planar cells hold
//     clearly more inliers (1 standard deviation), LOW_QUALITY when the whole
//     last layer prefers the result: the rings and the scene disagree;
//  5. until a result converges and passes the checks: the schedule again
//     from the guess turned about the input's centroid by each yaw seed
//     (retry), each result checked as in 4; the best verdict wins, then the
//     most inliers (every attempt scores the same points on the same last
//     layer);
//  6. a converged result is DEGENERATE when a solution that any of these
//     runs converged to lies more than half a last-layer cell edge away and
//     has not clearly fewer inliers (InlierGainEvidence > -1): the data do
//     not decide between the two, and the direction to it is unbounded.

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

// Runs 1-6 above.
Attempt SolveAttempts(const RegistrationOptions& options,
                      const Problem& problem,
                      const Vector6d& initial_local,
                      double start_time_s,
                      AttemptsCost* cost);

}  // namespace internal
}  // namespace mlndt
