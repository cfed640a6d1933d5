#include "tools/common/registration_flags.h"

#include <gflags/gflags.h>

#include <vector>

#include "mlndt/common/internal/enum_strings.h"
#include "tools/common/list_flags.h"

// clang-format off
DEFINE_string(preset, "default",
              "default (the library's options) | paper (the paper's: n = 4, start layer 2, "
              "3 iterations a layer, plain sum over own cells, Newton); flags given "
              "explicitly override the preset");
DEFINE_string(method, "mlndt",
              "mlndt (layered map, Mahalanobis score) | ndt (conventional single-grid NDT, "
              "Gaussian score, Newton; the ML-NDT-only flags are refused)");
DEFINE_double(ndt_cell_size, mlndt::NdtOptions().cell_size_m,
              "--method=ndt: cell edge [m]; 0 = the paper's layer-2 cell (V / 64)^(1/3)");
DEFINE_double(ndt_outlier_ratio, mlndt::NdtOptions().outlier_ratio,
              "--method=ndt: Magnusson's outlier ratio in (0, 1) (PCL: 0.55)");
DEFINE_string(ndt_neighbors, mlndt::NdtNeighborsToString(mlndt::NdtOptions().neighbors),
              "--method=ndt: cells a point is scored in: direct1 (its own) | direct7 (+6 faces)");
DEFINE_int32(ndt_max_iterations, mlndt::NdtOptions().max_iterations,
             "--method=ndt: Newton iteration cap");
DEFINE_double(ndt_max_step, mlndt::NdtOptions().max_step_norm,
              "--method=ndt: longest Newton step ||delta xi|| (m and rad); 0 = unbounded");
DEFINE_string(backend, "ceres", "ceres | newton | lm");
DEFINE_string(sampling, "gbs", "gbs | random | all | voxel_centroid");
DEFINE_double(random_fraction, mlndt::SamplingOptions().random_fraction,
              "Fraction of the input kept by --sampling=random");
DEFINE_double(gbs_cell_size, mlndt::SamplingOptions().gbs_cell_size_m, "GBS cell edge [m]");
DEFINE_int32(start_layer, mlndt::LayerScheduleOptions().start_layer,
             "1-based start layer s; <= 0 counts from the finest (0 = last layer)");
DEFINE_int32(num_layers, mlndt::LayeredGridOptions().num_layers,
             "Number of layers n (used when --finest_cell_size=0)");
DEFINE_int32(division_constant, mlndt::LayeredGridOptions().division_constant,
             "q: layer i has about q^i cells");
DEFINE_double(finest_cell_size, mlndt::LayeredGridOptions().finest_cell_size_m,
              "When > 0, n is the smallest layer count whose finest cell is <= this [m]");
DEFINE_int32(min_points_per_cell, mlndt::LayeredGridOptions().min_points_per_cell,
             "Points a cell needs to keep a distribution");
DEFINE_double(min_eigenvalue, mlndt::CellRegularization().min_eigenvalue_m2,
              "Absolute floor on cell covariance eigenvalues [m^2]");
DEFINE_double(min_eigenvalue_ratio, mlndt::CellRegularization().min_eigenvalue_ratio,
              "Cell eigenvalues are floored at this fraction of the largest (paper: 0.01)");
DEFINE_string(coarse_weighting, "finest_cells",
              "Weights in the coarse layers' moments: points | finest_cells (every finest "
              "cell alike)");
DEFINE_double(min_range, mlndt::RangeFilterOptions().min_range_m,
              "Input (and reference) points closer than this to the cloud's origin are "
              "dropped [m]. The range filters measure from the origin: the sensor for a "
              "scan in its sensor frame; for a map-frame (e.g. UTM) cloud set "
              "--min_range=0 --saturated_range_fraction=0");
DEFINE_double(max_range, mlndt::RangeFilterOptions().max_range_m,
              "Points farther than this from the cloud's origin (the sensor, in its "
              "sensor frame) are dropped [m]; 0 keeps all");
DEFINE_double(saturated_range_fraction, mlndt::RangeFilterOptions().saturated_range_fraction,
              "Points at the largest range (distance from the cloud's origin, the sensor "
              "in its sensor frame) are dropped when at least this fraction of the scan "
              "is there (0 = off)");
DEFINE_int32(iterations_per_layer, mlndt::LayerScheduleOptions().iterations_per_layer,
             "Iterations on each layer before the last");
DEFINE_int32(max_iterations, mlndt::LayerScheduleOptions().max_final_iterations,
             "Iteration cap on the last layer");
DEFINE_double(step_tolerance, mlndt::LayerScheduleOptions().step_tolerance,
              "Convergence: update norm on the last layer (NDT: of its Newton steps)");
DEFINE_double(coarse_step_tolerance, mlndt::LayerScheduleOptions().coarse_step_tolerance,
              "A coarse layer ends early below this update norm (0 = fixed iterations)");
DEFINE_int32(max_coarse_point_stride, mlndt::LayerScheduleOptions().max_coarse_point_stride,
             "Layer i of n uses every min(2^(n-i), this)-th sample (1 = all)");
DEFINE_string(unmatched, "nearest_cell", "zero_residual | nearest_cell");
DEFINE_string(loss, "cauchy", "none | huber | cauchy");
DEFINE_double(loss_scale, mlndt::ObjectiveOptions().loss_scale,
              "Mahalanobis distance where the robust loss bends");
DEFINE_string(linear_solver, "dense_normal_cholesky", "Ceres linear solver type");
DEFINE_string(trust_region, "levenberg_marquardt", "Ceres trust-region strategy");
DEFINE_int32(threads, 1,
             "Threads for the map build and the backend (Ceres evaluator threads, or OpenMP "
             "threads for newton and lm); with > 1 on a loaded machine set "
             "OMP_WAIT_POLICY=passive");
DEFINE_uint64(seed, mlndt::SamplingOptions().seed, "Sampling seed");
DEFINE_string(initial_uncertainty, "",
              "How far the initial guess may be off: translation_m,rotation_deg (e.g. 0.5,5); "
              "picks the start layer, and a guess is never made worse; empty = unknown");
DEFINE_bool(quality_check, mlndt::QualityCheckOptions().enabled,
            "Report LOW_QUALITY/DEGENERATE instead of CONVERGENCE when the fit at the "
            "solution fails the check");
DEFINE_double(min_inlier_fraction, mlndt::QualityCheckOptions().min_inlier_fraction,
              "Quality check: least share of inliers (Mahalanobis distance < --inlier_gate)");
DEFINE_double(max_mean_score, mlndt::QualityCheckOptions().max_mean_score,
              "Quality check: largest mean score per matched point");
DEFINE_double(inlier_gate, mlndt::QualityCheckOptions().inlier_gate,
              "Quality check: Mahalanobis distance of an inlier");
DEFINE_double(min_constraint_ratio, mlndt::QualityCheckOptions().min_constraint_ratio,
              "Quality check: DEGENERATE below this weakest/strongest information ratio");
DEFINE_string(retry_yaw_seeds, "45,-45,90,-90,135,-135,180",
              "Yaw turns [deg] of the guess tried, in order, until a result converges and "
              "passes the quality check; empty = no retry");
// clang-format on

namespace mlndt {
namespace tools {
namespace {

// True when the flag was given on the command line.
bool Given(const char* name) {
  return !gflags::GetCommandLineFlagInfoOrDie(name).is_default;
}

bool ParseCeres(CeresBackendOptions* ceres, std::string* error) {
  std::string upper = FLAGS_linear_solver;
  UpperCase(&upper);
  if (!ceres::StringToLinearSolverType(upper, &ceres->linear_solver_type)) {
    *error = "--linear_solver=" + FLAGS_linear_solver +
             ": not a Ceres linear solver type";
    return false;
  }
  upper = FLAGS_trust_region;
  UpperCase(&upper);
  if (!ceres::StringToTrustRegionStrategyType(
          upper, &ceres->trust_region_strategy_type)) {
    *error = "--trust_region=" + FLAGS_trust_region +
             ": expected levenberg_marquardt or dogleg";
    return false;
  }
  return true;
}

bool ParseSampling(SamplingOptions* sampling, std::string* error) {
  if (Given("sampling") &&
      !StringToSamplingMethod(FLAGS_sampling, &sampling->method)) {
    *error = "--sampling=" + FLAGS_sampling +
             ": expected gbs, random, all or voxel_centroid";
    return false;
  }
  if (Given("random_fraction"))
    sampling->random_fraction = FLAGS_random_fraction;
  if (Given("gbs_cell_size")) sampling->gbs_cell_size_m = FLAGS_gbs_cell_size;
  if (Given("seed")) sampling->seed = FLAGS_seed;
  // A flag the chosen sampling does not read is refused, not ignored.
  const SamplingMethod method = sampling->method;
  const char* ignored = nullptr;
  if (Given("gbs_cell_size") && method != SamplingMethod::GBS) {
    ignored = "--gbs_cell_size applies to --sampling=gbs only";
  } else if (Given("random_fraction") && method != SamplingMethod::RANDOM) {
    ignored = "--random_fraction applies to --sampling=random only";
  } else if (Given("seed") && method != SamplingMethod::RANDOM &&
             method != SamplingMethod::GBS) {
    ignored = "--seed applies to --sampling=random or gbs only";
  }
  if (ignored != nullptr) {
    *error = std::string(ignored) + " (the sampling is " +
             SamplingMethodToString(method) + "; it would be ignored)";
    return false;
  }
  return true;
}

void ParseRangeFilter(RangeFilterOptions* filter) {
  if (Given("min_range")) filter->min_range_m = FLAGS_min_range;
  if (Given("max_range")) filter->max_range_m = FLAGS_max_range;
  if (Given("saturated_range_fraction")) {
    filter->saturated_range_fraction = FLAGS_saturated_range_fraction;
  }
}

void ParseCells(int* min_points, CellRegularization* regularization) {
  if (Given("min_points_per_cell")) *min_points = FLAGS_min_points_per_cell;
  if (Given("min_eigenvalue")) {
    regularization->min_eigenvalue_m2 = FLAGS_min_eigenvalue;
  }
  if (Given("min_eigenvalue_ratio")) {
    regularization->min_eigenvalue_ratio = FLAGS_min_eigenvalue_ratio;
  }
}

// The flags that only ML-NDT reads.
const std::vector<const char*> kMlNdtOnlyFlags = {"backend",
                                                  "start_layer",
                                                  "num_layers",
                                                  "division_constant",
                                                  "finest_cell_size",
                                                  "coarse_weighting",
                                                  "iterations_per_layer",
                                                  "max_iterations",
                                                  "coarse_step_tolerance",
                                                  "max_coarse_point_stride",
                                                  "unmatched",
                                                  "loss",
                                                  "loss_scale",
                                                  "linear_solver",
                                                  "trust_region",
                                                  "retry_yaw_seeds",
                                                  "initial_uncertainty"};
const std::vector<const char*> kNdtOnlyFlags = {"ndt_cell_size",
                                                "ndt_outlier_ratio",
                                                "ndt_neighbors",
                                                "ndt_max_iterations",
                                                "ndt_max_step"};

bool ParseSchedule(LayerScheduleOptions* schedule) {
  if (Given("start_layer")) schedule->start_layer = FLAGS_start_layer;
  if (Given("iterations_per_layer")) {
    schedule->iterations_per_layer = FLAGS_iterations_per_layer;
  }
  if (Given("max_iterations")) {
    schedule->max_final_iterations = FLAGS_max_iterations;
  }
  if (Given("step_tolerance")) schedule->step_tolerance = FLAGS_step_tolerance;
  if (Given("coarse_step_tolerance")) {
    schedule->coarse_step_tolerance = FLAGS_coarse_step_tolerance;
  }
  if (Given("max_coarse_point_stride")) {
    schedule->max_coarse_point_stride = FLAGS_max_coarse_point_stride;
  }
  return true;
}

// The verdict's flags: both methods are judged by the same check. The
// thresholds are refused with --quality_check=false, which ignores them.
bool ParseQualityCheck(QualityCheckOptions* check, std::string* error) {
  if (Given("quality_check")) check->enabled = FLAGS_quality_check;
  if (Given("min_inlier_fraction")) {
    check->min_inlier_fraction = FLAGS_min_inlier_fraction;
  }
  if (Given("max_mean_score")) check->max_mean_score = FLAGS_max_mean_score;
  if (Given("inlier_gate")) check->inlier_gate = FLAGS_inlier_gate;
  if (Given("min_constraint_ratio")) {
    check->min_constraint_ratio = FLAGS_min_constraint_ratio;
  }
  if (check->enabled) return true;
  for (const char* flag : {"min_inlier_fraction",
                           "max_mean_score",
                           "inlier_gate",
                           "min_constraint_ratio"}) {
    if (Given(flag)) {
      *error = std::string("--") + flag +
               " is a quality-check threshold; it is ignored with "
               "--quality_check=false";
      return false;
    }
  }
  return true;
}

bool ParseTrust(RegistrationOptions* options, std::string* error) {
  if (!ParseQualityCheck(&options->quality_check, error)) return false;
  if (Given("retry_yaw_seeds") &&
      !ParseNumberList(FLAGS_retry_yaw_seeds, &options->retry.yaw_seeds_deg)) {
    *error = "--retry_yaw_seeds=" + FLAGS_retry_yaw_seeds +
             ": expected comma-separated angles [deg]";
    return false;
  }
  if (!FLAGS_initial_uncertainty.empty()) {
    std::vector<double> v;
    if (!ParseNumberList(FLAGS_initial_uncertainty, &v) || v.size() != 2) {
      *error = "--initial_uncertainty=" + FLAGS_initial_uncertainty +
               ": expected translation_m,rotation_deg";
      return false;
    }
    options->initial_uncertainty.given = true;
    options->initial_uncertainty.translation_m = v[0];
    options->initial_uncertainty.rotation_deg = v[1];
  }
  return true;
}

bool ParseMlNdt(RegistrationOptions* options, std::string* error) {
  if (FLAGS_preset == "paper") {
    *options = PaperRegistrationOptions();
  } else if (FLAGS_preset != "default") {
    *error = "--preset=" + FLAGS_preset + ": expected default or paper";
    return false;
  }
  if (Given("backend") &&
      !StringToBackendType(FLAGS_backend, &options->backend.type)) {
    *error = "--backend=" + FLAGS_backend + ": expected ceres, newton or lm";
    return false;
  }
  if (Given("unmatched") &&
      !StringToUnmatchedPolicy(FLAGS_unmatched,
                               &options->objective.unmatched_policy)) {
    *error = "--unmatched=" + FLAGS_unmatched +
             ": expected zero_residual or nearest_cell";
    return false;
  }
  if (Given("loss") &&
      !StringToLossType(FLAGS_loss, &options->objective.loss)) {
    *error = "--loss=" + FLAGS_loss + ": expected none, huber or cauchy";
    return false;
  }
  if (Given("loss_scale")) options->objective.loss_scale = FLAGS_loss_scale;
  if (Given("loss_scale") && options->objective.loss == LossType::NONE) {
    *error = "--loss_scale is ignored with --loss=none (no robust loss)";
    return false;
  }
  if (options->backend.type != BackendType::CERES) {
    for (const char* flag : {"linear_solver", "trust_region"}) {
      if (Given(flag)) {
        *error = std::string("--") + flag +
                 " applies to --backend=ceres only (" + "the backend is " +
                 BackendTypeToString(options->backend.type) +
                 "; it would be ignored)";
        return false;
      }
    }
  }
  if (!ParseTrust(options, error) ||
      !ParseCeres(&options->backend.ceres, error) ||
      !ParseSampling(&options->sampling, error) ||
      !ParseSchedule(&options->schedule)) {
    return false;
  }
  LayeredGridOptions& grid = options->grid;
  if (Given("num_layers")) grid.num_layers = FLAGS_num_layers;
  if (Given("division_constant")) {
    grid.division_constant = FLAGS_division_constant;
  }
  if (Given("finest_cell_size")) {
    grid.finest_cell_size_m = FLAGS_finest_cell_size;
  }
  if (Given("num_layers") && grid.finest_cell_size_m > 0.0) {
    *error =
        "--num_layers is ignored while --finest_cell_size > 0 (n is derived "
        "from it): give --finest_cell_size=0 with --num_layers";
    return false;
  }
  if (Given("coarse_weighting") &&
      !StringToCoarseWeighting(FLAGS_coarse_weighting,
                               &grid.coarse_weighting)) {
    *error = "--coarse_weighting=" + FLAGS_coarse_weighting +
             ": expected points or finest_cells";
    return false;
  }
  ParseCells(&grid.min_points_per_cell, &grid.regularization);
  ParseRangeFilter(&options->range_filter);
  options->num_threads = FLAGS_threads;
  return options->IsValid(error);
}

bool ParseNdt(NdtOptions* options, std::string* error) {
  if (!StringToNdtNeighbors(FLAGS_ndt_neighbors, &options->neighbors)) {
    *error = "--ndt_neighbors=" + FLAGS_ndt_neighbors +
             ": expected direct1 or direct7";
    return false;
  }
  options->cell_size_m = FLAGS_ndt_cell_size;
  options->outlier_ratio = FLAGS_ndt_outlier_ratio;
  options->max_iterations = FLAGS_ndt_max_iterations;
  options->max_step_norm = FLAGS_ndt_max_step;
  if (!ParseQualityCheck(&options->quality_check, error)) return false;
  options->step_tolerance = FLAGS_step_tolerance;
  options->num_threads = FLAGS_threads;
  ParseCells(&options->min_points_per_cell, &options->regularization);
  ParseRangeFilter(&options->range_filter);
  return ParseSampling(&options->sampling, error) && options->IsValid(error);
}

}  // namespace

bool MatcherOptionsFromFlags(MatcherOptions* options, std::string* error) {
  if (!StringToMethod(FLAGS_method, &options->method)) {
    *error = "--method=" + FLAGS_method + ": expected mlndt or ndt";
    return false;
  }
  const bool ndt = options->method == Method::NDT;
  for (const char* flag : ndt ? kMlNdtOnlyFlags : kNdtOnlyFlags) {
    if (Given(flag)) {
      *error = std::string("--") + flag +
               " does not apply to --method=" + FLAGS_method;
      return false;
    }
  }
  if (ndt && Given("preset")) {
    *error = "--preset does not apply to --method=ndt";
    return false;
  }
  return ndt ? ParseNdt(&options->ndt, error)
             : ParseMlNdt(&options->mlndt, error);
}

bool RangeFilterOptionsFromFlags(RangeFilterOptions* filter,
                                 std::string* error) {
  ParseRangeFilter(filter);
  if (filter->IsValid(error)) return true;
  for (const char* flag :
       {"saturated_range_fraction", "min_range", "max_range"}) {
    if (error->find(flag) != std::string::npos) {
      *error = std::string("--") + flag + ": " + *error;
      break;
    }
  }
  return false;
}

bool RegistrationOptionsFromFlags(RegistrationOptions* options,
                                  std::string* error) {
  MatcherOptions matcher;
  if (!MatcherOptionsFromFlags(&matcher, error)) return false;
  if (matcher.method != Method::MLNDT) {
    *error = "--method=" + FLAGS_method + ": this tool runs ML-NDT only";
    return false;
  }
  *options = matcher.mlndt;
  return true;
}

}  // namespace tools
}  // namespace mlndt
