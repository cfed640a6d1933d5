#pragma once

// The registration facade, shaped like ceres::Solve:
//
//   RegistrationOptions options;
//   RegistrationSummary summary;
//   Register(options, reference_map, input, initial_reference_from_input,
//   &summary); if (summary.IsSolutionUsable())
//   use(summary.reference_from_input);
//
// It samples the input scan (Section 4.3), runs the layer schedule
// (Table 1) with the chosen backend, and reports the pose, a per-iteration
// trace, counts, timings, the final score and the score's Hessian with the
// pose covariance derived from it. Invalid options or unusable input give a
// FAILURE summary with a message; nothing aborts.
//
// RegistrationOptions::method selects the algorithm: ML-NDT (the layered map
// and the Mahalanobis score, Section 4), or the conventional single-grid NDT
// the paper compares against (Section 3, Eq. 4; options.ndt), minimised by
// the Newton backend.

#include <ceres/types.h>

#include <string>
#include <vector>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/ndt_gaussian_score.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/ceres_backend.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"
#include "mlndt/solvers/newton_backend.h"

namespace mlndt {

enum class Method {
  MLNDT,  // Layered map, Mahalanobis score (Section 4), layer schedule.
  NDT,    // Conventional NDT: one grid, Gaussian score (Section 3, Eq. 4).
};

const char* MethodToString(Method method);
bool StringToMethod(std::string value, Method* method);

// The conventional NDT baseline (Method::NDT; Biber & Strasser, Magnusson's
// P2D-NDT). The grid's min_points_per_cell and covariance regularisation
// are RegistrationOptions::grid's, the input sampling is options.sampling,
// the minimiser is MinimizeNewton with options.newton (full Hessian, line
// search) and a bounded step (max_step_norm), and convergence is
// options.schedule.step_tolerance on the update norm. The backend, loss and
// unmatched-point policy do not apply.
struct NdtBaselineOptions {
  // Cell edge [m]. 0: the paper's comparison cell, one layer-2 cell of the
  // ML-NDT map over the reference box, (V / 64)^(1/3) (grid/single_grid.h);
  // ~15 m on a KITTI scan. PCL users run 1-2 m outdoors. Measured on the
  // bundled KITTI consecutive pairs from identity (0.86 m apart; success =
  // 0.2 m and 1 deg): the paper's cell 5 of 7 (its coarse model ends
  // 0.2-0.4 m off on the others), 1 m 2 of 7 (too small for that motion),
  // 2-6 m 7 of 7. PCL's NDT measured alike (1, 7, 7, 1 of 7 at 1, 2, 4,
  // 15 m). >= 0.
  double cell_size_m = 0.0;
  // Magnusson's outlier ratio r in (0, 1) (cost/ndt_gaussian_score.h).
  double outlier_ratio = 0.55;
  // Cells a point is scored in: its own (DIRECT1, as the paper) or also the
  // 6 face neighbours (DIRECT7). On the KITTI consecutive pairs (from
  // identity / from 42 starts up to 1 m and 5 deg off) DIRECT7 was better
  // only with 1 m cells (3 vs 2 of 7, 42 vs 41 of 42), much worse with the
  // paper's cell (0 vs 5, 0 vs 21) and 6 m (6 vs 7, 32 vs 39), equal with
  // 2-4 m, and 3x slower. (On the synthetic street scene, whose 1 m cells
  // are sparse, DIRECT7 widens the 1 m basin from ~0.1 m to ~1 m.)
  NdtNeighbors neighbors = NdtNeighbors::DIRECT1;
  int max_iterations = 50;  // Newton iterations. >= 1.
  // Longest Newton step ||delta xi|| (metres and radians mixed, as the
  // update norm); 0 = unbounded. Away from the minimum the Gaussian score's
  // Hessian is indefinite, and lifted by a tiny multiple of I its Newton
  // step runs hundreds of metres along the negative curvature, which the
  // line search's halvings cannot bring back (PCL's NDT bounds its step for
  // the same reason, step_size 0.1). The bounded step is the trust-region
  // one, -(H + mu I)^-1 g. On the KITTI pairs from 42 starts up to 1 m and
  // 5 deg off ground truth, 0.5 converged in 41, 42, 42 (1, 2, 4 m cells),
  // unbounded in 14, 21, 23. >= 0.
  double max_step_norm = 0.5;

  bool IsValid(std::string* error) const;
};

// Map options for registration of outdoor scans: the paper's q = 8 with n
// derived from a 2 m finest cell.
LayeredGridOptions DefaultRegistrationGridOptions();

// Schedule for registration without an initial guess: start on layer 1 and
// give every layer up to 6 iterations. The paper starts on layer 2 with 3
// iterations a layer; on KITTI pairs pushed off by up to 10 m / 45 deg that
// converged in 22 (layer 2) and 28 (3 iterations) of 35 starts, ours in 35.
// Coarse layers use every 8th sample at most (layer i of n every
// min(2^(n-i), 8)-th): the same 35 of 35 and the same final poses, at about
// half the time.
LayerScheduleOptions DefaultRegistrationScheduleOptions();

struct RegistrationOptions {
  // ML-NDT, or the conventional NDT baseline (options.ndt).
  Method method = Method::MLNDT;
  NdtBaselineOptions ndt;

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
  // over points in the hand-written backends. >= 1. (The map build has its
  // own, grid.num_threads.) OpenMP threads busy-wait between parallel
  // regions: on a loaded machine, run with OMP_WAIT_POLICY=passive.
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
  Method method = Method::MLNDT;  // The algorithm that ran.

  Vector6d initial_reference_from_input_xi = Vector6d::Zero();
  Vector6d reference_from_input_xi =
      Vector6d::Zero();  // (t [m], angles [rad]).
  Isometry3d reference_from_input = Isometry3d::Identity();

  std::vector<IterationRecord> trace;
  std::vector<int> iterations_per_layer;  // Index i - 1 for layer i.
  int num_iterations = 0;
  int start_layer = 0;
  int num_layers = 0;

  size_t input_points = 0;    // Finite input points.
  size_t sampled_points = 0;  // Points that became residuals.
  size_t matched_points =
      0;  // Sampled points in a cell at the solution (last layer).
  size_t unmatched_points = 0;

  double map_time_s = 0.0;  // Building the reference map (0 if given).
  double sampling_time_s = 0.0;
  double solve_time_s = 0.0;
  double total_time_s = 0.0;  // Everything after the clouds were loaded.

  size_t map_occupied_cells =
      0;  // Over all layers of the reference map (ML-NDT; 0 for NDT).
  size_t map_bytes =
      0;  // LayeredGrid::MemoryBytes() of the map (ML-NDT; 0 for NDT).

  // ML-NDT: Eq. (10) on the last layer. NDT: the Gaussian score (negated
  // Eq. 4 with Magnusson's d1, d2; <= 0, lower is better).
  double initial_score = 0.0;  // At the initial pose.
  double final_score = 0.0;    // At the solution.
  // ML-NDT: the Gauss-Newton Hessian of the final score w.r.t. xi, and the
  // covariance of xi derived from it as 2 H^-1 (the Laplace approximation
  // for whitened residuals of unit variance; zero when H is singular).
  // NDT: the full Newton Hessian of the Gaussian score (Magnusson Eq. 6.13),
  // and H^-1 as the covariance (the score approximates a negative
  // log-likelihood up to a constant; zero unless H is positive definite).
  // Units m and rad.
  Matrix6d hessian = Matrix6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();
  double ndt_cell_size_m = 0.0;  // NDT: the grid's cell edge [m]; 0 for ML-NDT.

  std::string BriefReport() const;
  std::string FullReport() const;
  bool IsSolutionUsable() const {
    return termination_type != TerminationType::FAILURE;
  }
};

// Registers `input` against a map built beforehand. Method::NDT needs the
// reference cloud (its own single grid): this overload then reports FAILURE.
void Register(const RegistrationOptions& options,
              const LayeredGrid& reference_map,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

// Builds the map of `reference` (ML-NDT: options.grid; NDT: one grid with
// options.ndt.cell_size_m), then registers.
void Register(const RegistrationOptions& options,
              const PointCloud& reference,
              const PointCloud& input,
              const Isometry3d& initial_reference_from_input,
              RegistrationSummary* summary);

}  // namespace mlndt
