#pragma once

// What a registration reports (ML-NDT's Register and the NDT baseline's
// RegisterNdt alike): termination, pose, per-iteration trace, counts,
// timings, scores, and the score's Hessian with the pose covariance derived
// from it. Shaped like ceres::Solver::Summary.

#include <cstdint>
#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/fit_quality.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/solvers/backend.h"

namespace mlndt {

class ResultTable;

struct RegistrationSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  // "ML-NDT" or "NDT": the algorithm that ran (for reports).
  std::string algorithm = "ML-NDT";

  Vector6d initial_reference_from_input_xi = Vector6d::Zero();
  // (t [m], angles [rad]), Eq. (11).
  Vector6d reference_from_input_xi = Vector6d::Zero();
  Isometry3d reference_from_input = Isometry3d::Identity();

  std::vector<IterationRecord> trace;
  std::vector<int> iterations_per_layer;  // Index i - 1 for layer i.
  int num_iterations = 0;  // Of the reported solution (trace.size()).
  // Schedule runs: 2 when the result was checked against the last layer
  // alone from the guess, more with yaw retries (attempts.h).
  int attempts = 0;
  // The work of the solve, free of machine noise: the sampled points
  // evaluated, summed over every iteration of every stage of every attempt
  // (a stage over every s-th sample counts a 1/s share). 0 for NDT.
  int64_t point_iterations = 0;
  int start_layer = 0;
  // With a prior (RegistrationOptions::initial_uncertainty): the free
  // directions along which the pose kept the initial guess's value and the
  // covariance the prior's (registration/internal/prior_hold.h); 0 when
  // none or no prior.
  int prior_held_directions = 0;
  int num_layers = 0;
  double finest_cell_size_m = 0.0;  // Cell edge of the last layer [m].

  size_t input_points = 0;           // Points of the input cloud.
  size_t range_filtered_points = 0;  // Of those, dropped by the range filter.
  size_t sampled_points = 0;         // Points that became residuals.
  // Sampled points in a cell at the solution (last layer), and the rest.
  size_t matched_points = 0;
  size_t unmatched_points = 0;

  double map_time_s = 0.0;  // Building the reference map (0 if given).
  double sampling_time_s = 0.0;
  double solve_time_s = 0.0;
  double total_time_s = 0.0;  // Everything after the clouds were loaded.

  // The fit at the solution on the last layer (fit_quality.h), and how well
  // it constrains the pose (quality_check.h): the verdict's evidence.
  FitQuality quality;
  ConstraintAnalysis constraints;

  size_t map_occupied_cells = 0;  // Over all layers of the reference map.
  size_t map_bytes = 0;           // LayeredGrid::MemoryBytes() of the map.

  // ML-NDT: Eq. (10) on the last layer. NDT: the Gaussian score (negated
  // Eq. 4 with Magnusson's d1, d2; <= 0, lower is better).
  double initial_score = 0.0;  // At the initial pose.
  double final_score = 0.0;    // At the solution.
  // ML-NDT: the Gauss-Newton Hessian of the final score w.r.t. xi, and the
  // covariance of xi derived from it as 2 H^-1 (the Laplace approximation
  // for whitened residuals of unit variance; zero when H is singular).
  // NDT: the full Newton Hessian of the Gaussian score (Magnusson Eq. 6.13),
  // and H^-1 as the covariance (zero unless H is positive definite).
  // Units m and rad. Along degenerate directions the variances are
  // infinite, or the prior's when one was given (prior_held_directions).
  Matrix6d hessian = Matrix6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();

  std::string BriefReport() const;
  std::string FullReport() const;
  // CONVERGENCE or NO_CONVERGENCE: the pose passed the quality check.
  bool IsSolutionUsable() const {
    return IsUsableTermination(termination_type);
  }
};

// RegistrationSummary's fields: name, unit, help (result_table.h), the
// nested FitQuality, ConstraintAnalysis and IterationRecord tables included.
// The JSON, Python and docs forms of a registration's result come from it.
const ResultTable& RegistrationSummaryTable();

}  // namespace mlndt
