#pragma once

// Registration flags shared by the tools (mlndt_align, mlndt_pairs): every
// RegistrationOptions field a user tunes, with the library's defaults.
// Include from exactly one translation unit per tool (it defines the flags).

#include <gflags/gflags.h>

#include <string>

#include "mlndt/common/enum_strings.h"
#include "mlndt/registration/registration.h"

DEFINE_string(
    method,
    "mlndt",
    "mlndt (layered map, Mahalanobis score) | ndt (conventional single-grid "
    "NDT, "
    "Gaussian score, Newton; --backend/--loss/--unmatched do not apply)");
DEFINE_double(
    ndt_cell_size,
    mlndt::NdtBaselineOptions().cell_size_m,
    "--method=ndt: cell edge [m]; 0 = the paper's layer-2 cell (V / 64)^(1/3)");
DEFINE_double(ndt_outlier_ratio,
              mlndt::NdtBaselineOptions().outlier_ratio,
              "--method=ndt: Magnusson's outlier ratio in (0, 1) (PCL: 0.55)");
DEFINE_string(
    ndt_neighbors,
    mlndt::NdtNeighborsToString(mlndt::NdtBaselineOptions().neighbors),
    "--method=ndt: cells a point is scored in: direct1 (its own) | direct7 (+6 "
    "faces)");
DEFINE_int32(ndt_max_iterations,
             mlndt::NdtBaselineOptions().max_iterations,
             "--method=ndt: Newton iteration cap");
DEFINE_double(ndt_max_step,
              mlndt::NdtBaselineOptions().max_step_norm,
              "--method=ndt: longest Newton step ||delta xi|| (m and rad); 0 = "
              "unbounded");
DEFINE_string(backend, "ceres", "ceres | newton | lm");
DEFINE_string(sampling, "gbs", "gbs | random | all | voxel_centroid");
DEFINE_double(random_fraction,
              0.15,
              "Fraction of the input kept by --sampling=random");
DEFINE_double(gbs_cell_size, 1.0, "GBS cell edge [m]");
DEFINE_int32(
    start_layer,
    mlndt::DefaultRegistrationScheduleOptions().start_layer,
    "1-based start layer s; <= 0 counts from the finest (0 = last layer)");
DEFINE_int32(num_layers,
             mlndt::DefaultRegistrationGridOptions().num_layers,
             "Number of layers n (used when --finest_cell_size=0)");
DEFINE_int32(division_constant,
             mlndt::DefaultRegistrationGridOptions().division_constant,
             "q: layer i has about q^i cells");
DEFINE_double(
    finest_cell_size,
    mlndt::DefaultRegistrationGridOptions().finest_cell_size_m,
    "When > 0, n is the smallest layer count whose finest cell is <= this [m]");
DEFINE_int32(min_points_per_cell,
             mlndt::DefaultRegistrationGridOptions().min_points_per_cell,
             "Points a cell needs to keep a distribution");
DEFINE_double(min_eigenvalue,
              mlndt::CellRegularization().min_eigenvalue_m2,
              "Absolute floor on cell covariance eigenvalues [m^2]");
DEFINE_double(min_eigenvalue_ratio,
              mlndt::CellRegularization().min_eigenvalue_ratio,
              "Cell eigenvalues are floored at this fraction of the largest "
              "(paper: 0.01)");
DEFINE_int32(iterations_per_layer,
             mlndt::DefaultRegistrationScheduleOptions().iterations_per_layer,
             "Iterations on each layer before the last");
DEFINE_int32(max_iterations,
             mlndt::DefaultRegistrationScheduleOptions().max_final_iterations,
             "Iteration cap on the last layer");
DEFINE_double(step_tolerance,
              mlndt::DefaultRegistrationScheduleOptions().step_tolerance,
              "Convergence: update norm on the last layer");
DEFINE_double(
    coarse_step_tolerance,
    mlndt::DefaultRegistrationScheduleOptions().coarse_step_tolerance,
    "A coarse layer ends early below this update norm (0 = fixed iterations)");
DEFINE_int32(
    max_coarse_point_stride,
    mlndt::DefaultRegistrationScheduleOptions().max_coarse_point_stride,
    "Layer i of n uses every min(2^(n-i), this)-th sample (1 = all)");
DEFINE_string(unmatched, "nearest_cell", "zero_residual | nearest_cell");
DEFINE_string(loss, "cauchy", "none | huber | cauchy");
DEFINE_double(loss_scale,
              mlndt::RegistrationOptions().loss_scale,
              "Mahalanobis distance where the robust loss bends");
DEFINE_string(linear_solver,
              "dense_normal_cholesky",
              "Ceres linear solver type");
DEFINE_string(trust_region,
              "levenberg_marquardt",
              "Ceres trust-region strategy");
DEFINE_int32(threads,
             1,
             "Threads: Ceres evaluator threads, or OpenMP threads (newton, "
             "lm), and OpenMP "
             "threads for the map build; with > 1 on a loaded machine set "
             "OMP_WAIT_POLICY=passive");
DEFINE_uint64(seed, 1, "Sampling seed");

namespace mlndt {
namespace tools {

// Fills *options from the flags; false with *error naming a bad value.
inline bool RegistrationOptionsFromFlags(RegistrationOptions* options,
                                         std::string* error) {
  if (!StringToMethod(FLAGS_method, &options->method)) {
    *error = "--method=" + FLAGS_method + ": expected mlndt or ndt";
    return false;
  }
  if (!StringToNdtNeighbors(FLAGS_ndt_neighbors, &options->ndt.neighbors)) {
    *error = "--ndt_neighbors=" + FLAGS_ndt_neighbors +
             ": expected direct1 or direct7";
    return false;
  }
  if (!StringToBackendType(FLAGS_backend, &options->backend)) {
    *error = "--backend=" + FLAGS_backend + ": expected ceres, newton or lm";
    return false;
  }
  if (!StringToSamplingMethod(FLAGS_sampling, &options->sampling.method)) {
    *error = "--sampling=" + FLAGS_sampling +
             ": expected gbs, random, all or voxel_centroid";
    return false;
  }
  if (!StringToUnmatchedPolicy(FLAGS_unmatched, &options->unmatched_policy)) {
    *error = "--unmatched=" + FLAGS_unmatched +
             ": expected zero_residual or nearest_cell";
    return false;
  }
  if (!StringToLossType(FLAGS_loss, &options->loss)) {
    *error = "--loss=" + FLAGS_loss + ": expected none, huber or cauchy";
    return false;
  }
  std::string upper = FLAGS_linear_solver;
  UpperCase(&upper);
  if (!ceres::StringToLinearSolverType(upper,
                                       &options->ceres.linear_solver_type)) {
    *error = "--linear_solver=" + FLAGS_linear_solver +
             ": not a Ceres linear solver type";
    return false;
  }
  upper = FLAGS_trust_region;
  UpperCase(&upper);
  if (!ceres::StringToTrustRegionStrategyType(
          upper, &options->ceres.trust_region_strategy_type)) {
    *error = "--trust_region=" + FLAGS_trust_region +
             ": expected levenberg_marquardt or dogleg";
    return false;
  }
  options->sampling.random_fraction = FLAGS_random_fraction;
  options->sampling.gbs_cell_size_m = FLAGS_gbs_cell_size;
  options->sampling.seed = FLAGS_seed;
  options->schedule.start_layer = FLAGS_start_layer;
  options->schedule.iterations_per_layer = FLAGS_iterations_per_layer;
  options->schedule.max_final_iterations = FLAGS_max_iterations;
  options->schedule.step_tolerance = FLAGS_step_tolerance;
  options->schedule.coarse_step_tolerance = FLAGS_coarse_step_tolerance;
  options->schedule.max_coarse_point_stride = FLAGS_max_coarse_point_stride;
  options->grid.num_layers = FLAGS_num_layers;
  options->grid.division_constant = FLAGS_division_constant;
  options->grid.finest_cell_size_m = FLAGS_finest_cell_size;
  options->grid.min_points_per_cell = FLAGS_min_points_per_cell;
  options->grid.regularization.min_eigenvalue_m2 = FLAGS_min_eigenvalue;
  options->grid.regularization.min_eigenvalue_ratio =
      FLAGS_min_eigenvalue_ratio;
  options->ndt.cell_size_m = FLAGS_ndt_cell_size;
  options->ndt.outlier_ratio = FLAGS_ndt_outlier_ratio;
  options->ndt.max_iterations = FLAGS_ndt_max_iterations;
  options->ndt.max_step_norm = FLAGS_ndt_max_step;
  options->loss_scale = FLAGS_loss_scale;
  options->num_threads = FLAGS_threads;
  options->grid.num_threads = FLAGS_threads;
  return options->IsValid(error);
}

}  // namespace tools
}  // namespace mlndt
