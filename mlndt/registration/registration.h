#pragma once

// The registration facade, shaped like ceres::Solve:
//
//   RegistrationOptions options;
//   RegistrationSummary summary;
//   Register(options, reference_map, input, initial_reference_from_input, &summary);
//   if (summary.IsSolutionUsable()) use(summary.reference_from_input);
//
// It samples the input scan (Section 4.3), runs the layer schedule
// (Table 1) with the chosen backend, and reports the pose, a per-iteration
// trace, counts, timings, the final score and the score's Hessian with the
// pose covariance derived from it. Invalid options or unusable input give a
// FAILURE summary with a message; nothing aborts.

#include <string>
#include <vector>

#include <ceres/types.h>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/ceres_backend.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"
#include "mlndt/solvers/newton_backend.h"

namespace mlndt {

// Map options for registration of outdoor scans: the paper's q = 8 with n
// derived from a 2 m finest cell.
LayeredGridOptions DefaultRegistrationGridOptions();

// Schedule for registration without an initial guess: start on layer 1 and
// give every layer up to 6 iterations. The paper starts on layer 2 with 3
// iterations a layer; on KITTI pairs pushed off by up to 10 m / 45 deg that
// converged in 23 (layer 2) and 29 (3 iterations) of 35 starts, ours in 35.
LayerScheduleOptions DefaultRegistrationScheduleOptions();

struct RegistrationOptions {
  // The reference map (used by the overload that builds it). Unlike the
  // paper's fixed n = 4, n is derived from a 2 m finest cell: on a KITTI
  // scan n = 4 leaves ~4-8 m cells, and 1-2 m is where single-grid NDT users
  // work; 2 m converged as often as 1 m on the KITTI pairs (35 of 35 starts)
  // in two thirds of the time.
  LayeredGridOptions grid = DefaultRegistrationGridOptions();

  // Which input points become residuals.
  SamplingOptions sampling;
  // Start layer, iterations per layer, convergence of the last layer.
  LayerScheduleOptions schedule = DefaultRegistrationScheduleOptions();
  BackendType backend = BackendType::CERES;
  CeresBackendOptions ceres;
  NewtonOptions newton;
  LevenbergMarquardtOptions levenberg_marquardt;
  // Threads for every backend: Ceres' evaluator threads, or OpenMP threads
  // over points in the hand-written backends. >= 1.
  int num_threads = 1;
  // What a point in no occupied cell contributes (cell_match.h). Measured on
  // KITTI pairs pushed off by up to 10 m / 45 deg: NEAREST_CELL converged
  // in 35 of 35 starts, ZERO_RESIDUAL in 34 (README, "Defaults").
  UnmatchedPolicy unmatched_policy = UnmatchedPolicy::NEAREST_CELL;
  // The paper's plain sum (NONE) lets dynamic objects and parts seen by one
  // scan only pull the estimate: on the bundled Velodyne pair it ends 7 cm
  // and 0.9 deg from the reference result, CAUCHY 1.6 cm and 0.3 deg.
  LossType loss = LossType::CAUCHY;
  double loss_scale = 3.0;  // Mahalanobis distance where the loss bends. > 0.
  // The result is reported as FAILURE when fewer than this fraction of the
  // sampled points are matched to a cell at the solution. In [0, 1].
  double min_matched_fraction = 0.05;

  bool IsValid(std::string* error) const;
};

struct RegistrationSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;

  Vector6d initial_reference_from_input_xi = Vector6d::Zero();
  Vector6d reference_from_input_xi = Vector6d::Zero();  // (t [m], angles [rad]).
  Isometry3d reference_from_input = Isometry3d::Identity();

  std::vector<IterationRecord> trace;
  std::vector<int> iterations_per_layer;  // Index i - 1 for layer i.
  int num_iterations = 0;
  int start_layer = 0;
  int num_layers = 0;

  size_t input_points = 0;    // Finite input points.
  size_t sampled_points = 0;  // Points that became residuals.
  size_t matched_points = 0;  // Sampled points in a cell at the solution (last layer).
  size_t unmatched_points = 0;

  double map_time_s = 0.0;       // Building the reference map (0 if given).
  double sampling_time_s = 0.0;
  double solve_time_s = 0.0;
  double total_time_s = 0.0;     // Everything after the clouds were loaded.

  double initial_score = 0.0;  // Eq. (10) on the last layer at the initial pose.
  double final_score = 0.0;    // Eq. (10) on the last layer at the solution.
  // Gauss-Newton Hessian of the final score w.r.t. xi, and the covariance of
  // xi derived from it as 2 H^-1 (the Laplace approximation for whitened
  // residuals of unit variance; zero when H is singular). Units m and rad.
  Matrix6d hessian = Matrix6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();

  std::string BriefReport() const;
  std::string FullReport() const;
  bool IsSolutionUsable() const { return termination_type != TerminationType::FAILURE; }
};

// Registers `input` against a map built beforehand.
void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

// Builds the map of `reference` with options.grid, then registers.
void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

}  // namespace mlndt
