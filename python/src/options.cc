#include "python/src/options.h"

#include <ceres/types.h>

#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/grid/ndt_cell.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/sampling/point_sampler.h"
#include "mlndt/schedule/layer_scheduler.h"
#include "mlndt/solvers/backend_factory.h"

// One binding per option struct, field by field in the order of its header
// (the header is the reference for meaning and range; the doc strings here
// are one-line summaries). A field added to a struct is one line here and one
// in python/mlndt/__init__.pyi (python/tests/test_stubs.py checks the stub).

namespace mlndt {
namespace python {
namespace {

// ceres' StringToX take the value by value like ours.
bool StringToLinearSolver(std::string value, ceres::LinearSolverType* type) {
  return ceres::StringToLinearSolverType(std::move(value), type);
}
bool StringToTrustRegion(std::string value,
                         ceres::TrustRegionStrategyType* type) {
  return ceres::StringToTrustRegionStrategyType(std::move(value), type);
}

const StructBinding<CellRegularization>& CellRegularizationBinding() {
  using S = CellRegularization;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("CellRegularization");
    b.Field("min_eigenvalue_ratio",
            &S::min_eigenvalue_ratio,
            "Cell eigenvalues floored at this fraction of the largest "
            "(Section 4.1: 0.01). In [1e-9, 1].")
        .Field("min_eigenvalue_m2",
               &S::min_eigenvalue_m2,
               "Absolute floor on every cell eigenvalue [m^2]. In [0, 1e6].");
    return b;
  }();
  return binding;
}

const StructBinding<SamplingOptions>& SamplingOptionsBinding() {
  using S = SamplingOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("SamplingOptions");
    b.EnumField("method",
                &S::method,
                SamplingMethodToString,
                StringToSamplingMethod,
                "Which input points become residuals (Section 4.3).")
        .Field("random_fraction",
               &S::random_fraction,
               "RANDOM: fraction of the input kept, in (0, 1] (used when "
               "random_count == 0).")
        .Field("random_count",
               &S::random_count,
               "RANDOM: exact number of points kept when > 0.")
        .Field("gbs_cell_size_m", &S::gbs_cell_size_m, "GBS: cell edge [m].")
        .Field("gbs_points_per_cell",
               &S::gbs_points_per_cell,
               "GBS: a cell with more points gives this many, at random.")
        .Field("gbs_min_points_per_cell",
               &S::gbs_min_points_per_cell,
               "GBS: a cell with fewer points gives none (>= 1).")
        .Field(
            "voxel_size_m", &S::voxel_size_m, "VOXEL_CENTROID: voxel edge [m].")
        .Field("seed", &S::seed, "Seed of every random choice.")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<LayerScheduleOptions>& LayerScheduleOptionsBinding() {
  using S = LayerScheduleOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("LayerScheduleOptions");
    b.Field("start_layer",
            &S::start_layer,
            "1-based start layer s; <= 0 counts from the finest (0 = last "
            "layer). In [-16, 16].")
        .Field("iterations_per_layer",
               &S::iterations_per_layer,
               "Iterations on every layer but the last. In [1, 1000].")
        .Field("max_final_iterations",
               &S::max_final_iterations,
               "Cap on the last layer's iterations. In [1, 10000].")
        .Field("step_tolerance",
               &S::step_tolerance,
               "The last layer converges when a successful step has "
               "||delta xi|| below this (m and rad). In [1e-12, 1].")
        .Field("coarse_step_tolerance",
               &S::coarse_step_tolerance,
               "A coarse layer ends early below this update norm; 0 runs "
               "every coarse layer fully. In [0, 1].")
        .Field("max_coarse_point_stride",
               &S::max_coarse_point_stride,
               "Layer i of n uses every min(2^(n-i), this)-th sample (1 = "
               "all). In [1, 1024].")
        .Field("cells_per_uncertainty",
               &S::cells_per_uncertainty,
               "With a known guess uncertainty d, start on the finest layer "
               "whose cell is >= this * d. In [0.5, 100].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<ObjectiveOptions>& ObjectiveOptionsBinding() {
  using S = ObjectiveOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("ObjectiveOptions");
    b.EnumField("unmatched_policy",
                &S::unmatched_policy,
                UnmatchedPolicyToString,
                StringToUnmatchedPolicy,
                "What a point in no occupied cell contributes (cell_match.h).")
        .EnumField("loss",
                   &S::loss,
                   LossTypeToString,
                   StringToLossType,
                   "Robust loss rho on the per-point score (NONE: the paper's "
                   "plain sum, Eq. 10).")
        .Field("loss_scale",
               &S::loss_scale,
               "Mahalanobis distance where the loss bends. In [1e-3, 1e3].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<CeresBackendOptions>& CeresBackendOptionsBinding() {
  using S = CeresBackendOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("CeresBackendOptions");
    b.EnumField("linear_solver_type",
                &S::linear_solver_type,
                ceres::LinearSolverTypeToString,
                StringToLinearSolver,
                "Ceres linear solver.")
        .EnumField("trust_region_strategy_type",
                   &S::trust_region_strategy_type,
                   ceres::TrustRegionStrategyTypeToString,
                   StringToTrustRegion,
                   "Ceres trust-region strategy.")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<NewtonOptions>& NewtonOptionsBinding() {
  using S = NewtonOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("NewtonOptions");
    b.Field("line_search",
            &S::line_search,
            "Backtracking line search (halving the step until the score "
            "decreases).")
        .Field("max_line_search_steps",
               &S::max_line_search_steps,
               "Halvings before the step is rejected. In [1, 60].")
        .Field("min_eigenvalue_ratio",
               &S::min_eigenvalue_ratio,
               "H is lifted by gamma I until its smallest eigenvalue is this "
               "fraction of its largest. In [1e-15, 1].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<LevenbergMarquardtOptions>&
LevenbergMarquardtOptionsBinding() {
  using S = LevenbergMarquardtOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("LevenbergMarquardtOptions");
    b.Field("initial_lambda_factor",
            &S::initial_lambda_factor,
            "lambda_0 / mean(diag(J^T J)). In [1e-15, 1e6].")
        .Field("lambda_decrease",
               &S::lambda_decrease,
               "lambda divisor after a successful step. In (1, 1e6].")
        .Field("lambda_increase",
               &S::lambda_increase,
               "lambda factor after a rejected step. In (1, 1e6].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<BackendOptions>& BackendOptionsBinding() {
  using S = BackendOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("BackendOptions");
    b.EnumField("type",
                &S::type,
                BackendTypeToString,
                StringToBackendType,
                "Which minimiser (\"lm\" names LEVENBERG_MARQUARDT).")
        .Nested("ceres",
                &S::ceres,
                CeresBackendOptionsBinding(),
                "Options of type CERES.")
        .Nested("newton",
                &S::newton,
                NewtonOptionsBinding(),
                "Options of type NEWTON.")
        .Nested("levenberg_marquardt",
                &S::levenberg_marquardt,
                LevenbergMarquardtOptionsBinding(),
                "Options of type LEVENBERG_MARQUARDT.")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<QualityCheckOptions>& QualityCheckOptionsBinding() {
  using S = QualityCheckOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("QualityCheckOptions");
    b.Field("enabled",
            &S::enabled,
            "Off: the solver's termination is reported as it is.")
        .Field("inlier_gate",
               &S::inlier_gate,
               "Mahalanobis distance below which a point is an inlier. In "
               "[0.5, 10].")
        .Field("min_inlier_fraction",
               &S::min_inlier_fraction,
               "LOW_QUALITY below this share of inliers. In [0, 1].")
        .Field("max_mean_score",
               &S::max_mean_score,
               "LOW_QUALITY above this mean score per matched point. In (0, "
               "1e6].")
        .Field("min_constraint_ratio",
               &S::min_constraint_ratio,
               "DEGENERATE below this weakest/strongest information ratio. In "
               "[0, 1).")
        .Field("max_flatness",
               &S::max_flatness,
               "DEGENERATE when one cell along a weak direction keeps more "
               "than this share of the inliers (and min_probe_evidence). In "
               "(0, 1]; 1 = off.")
        .Field("min_probe_evidence",
               &S::min_probe_evidence,
               "...unless the net inlier loss there is at least this many "
               "standard deviations. >= 0.")
        .Field("min_fit_points",
               &S::min_fit_points,
               "LOW_QUALITY with fewer sampled points than this. In [0, 1e6].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<InitialGuessUncertainty>& InitialGuessUncertaintyBinding() {
  using S = InitialGuessUncertainty;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("InitialGuessUncertainty");
    b.Field("given", &S::given, "False: nothing is known about the guess.")
        .Field("translation_m",
               &S::translation_m,
               "How far the guess may be off [m]. In [0, 1e4].")
        .Field("rotation_deg",
               &S::rotation_deg,
               "How far the guess may be turned [deg]. In [0, 180].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<RetryOptions>& RetryOptionsBinding() {
  using S = RetryOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("RetryOptions");
    b.Field("yaw_seeds_deg",
            &S::yaw_seeds_deg,
            "Yaw turns of the guess [deg] tried in order when a result fails "
            "the quality check; [] = no retry. At most 36, each in [-180, "
            "180].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

// Pops "preset" from `kwargs` (default "default").
std::string PopPreset(py::dict* kwargs) {
  if (!kwargs->contains("preset")) return "default";
  const py::object value = (*kwargs)["preset"];
  PyDict_DelItemString(kwargs->ptr(), "preset");
  if (!py::isinstance<py::str>(value)) {
    ThrowValueError("invalid option: preset = " + DescribeValue(value) +
                    "; expected \"default\" or \"paper\"");
  }
  const std::string preset = value.cast<std::string>();
  if (preset != "default" && preset != "paper") {
    ThrowValueError("invalid option: preset = '" + preset +
                    "'; expected \"default\" or \"paper\"");
  }
  return preset;
}

template <typename S>
void ValidateOrThrow(const StructBinding<S>& binding, const S& options) {
  std::string error;
  if (!binding.Validate(options, "", &error)) ThrowValueError(error);
}

}  // namespace

const StructBinding<RangeFilterOptions>& RangeFilterOptionsBinding() {
  using S = RangeFilterOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("RangeFilterOptions");
    b.Field("min_range_m",
            &S::min_range_m,
            "Points closer than this to the sensor are dropped [m]. In [0, "
            "1e3].")
        .Field("max_range_m",
               &S::max_range_m,
               "Points farther than this are dropped [m]; 0 keeps every "
               "range.")
        .Field("saturated_range_fraction",
               &S::saturated_range_fraction,
               "Points at the largest range are dropped when at least this "
               "fraction of the cloud is there; 0 = off. In [0, 1].")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<LayeredGridOptions>& LayeredGridOptionsBinding() {
  using S = LayeredGridOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("LayeredGridOptions");
    b.Field("division_constant",
            &S::division_constant,
            "q: layer i has about q^i cells over the bounding box. In [2, "
            "512].")
        .Field("num_layers",
               &S::num_layers,
               "n, used when finest_cell_size_m == 0. In [1, max_num_layers].")
        .Field("finest_cell_size_m",
               &S::finest_cell_size_m,
               "When > 0, n is the smallest layer count whose finest cell is "
               "<= this [m]. 0, or in [1e-3, 1e5].")
        .Field("cell_size_m",
               &S::cell_size_m,
               "When > 0, one layer of cells of exactly this edge [m] (the "
               "conventional NDT grid). 0, or in [1e-3, 1e5].")
        .Field("max_num_layers",
               &S::max_num_layers,
               "Upper bound on n. In [1, 16].")
        .Field("min_points_per_cell",
               &S::min_points_per_cell,
               "A cell keeps a distribution with at least this many points. "
               "In [4, 1e6].")
        .Nested("regularization",
                &S::regularization,
                CellRegularizationBinding(),
                "Covariance regularisation (ndt_cell.h).")
        .EnumField("coarse_weighting",
                   &S::coarse_weighting,
                   CoarseWeightingToString,
                   StringToCoarseWeighting,
                   "Weights of the points in the coarse layers' moments.")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

const StructBinding<RegistrationOptions>& RegistrationOptionsBinding() {
  using S = RegistrationOptions;
  static const StructBinding<S> binding = [] {
    StructBinding<S> b("RegistrationOptions");
    b.Nested("range_filter",
             &S::range_filter,
             RangeFilterOptionsBinding(),
             "Returns dropped from the input (and from the reference when "
             "the map is built here).")
        .Nested("grid",
                &S::grid,
                LayeredGridOptionsBinding(),
                "The reference map (not for LayeredMap.register: the map "
                "exists).")
        .Nested("sampling",
                &S::sampling,
                SamplingOptionsBinding(),
                "Which input points become residuals (Section 4.3).")
        .Nested("schedule",
                &S::schedule,
                LayerScheduleOptionsBinding(),
                "Start layer, iterations per layer, convergence (Table 1).")
        .Nested("objective",
                &S::objective,
                ObjectiveOptionsBinding(),
                "What is minimised (Eq. 10).")
        .Nested("backend",
                &S::backend,
                BackendOptionsBinding(),
                "Which minimiser, with its options.")
        .Field("num_threads",
               &S::num_threads,
               "Threads for the map build and the backend. In [1, 256].")
        .Field("min_matched_fraction",
               &S::min_matched_fraction,
               "FAILURE when fewer than this fraction of the sampled points "
               "are matched at the solution. In [0, 1].")
        .Nested("quality_check",
                &S::quality_check,
                QualityCheckOptionsBinding(),
                "Whether the result can be trusted (quality_check.h).")
        .Nested("initial_uncertainty",
                &S::initial_uncertainty,
                InitialGuessUncertaintyBinding(),
                "How good the initial guess is; the initial_uncertainty "
                "argument sets it.")
        .Nested("retry",
                &S::retry,
                RetryOptionsBinding(),
                "Runs from turned guesses when the first fails the quality "
                "check.")
        .Validator(&S::IsValid);
    return b;
  }();
  return binding;
}

RegistrationOptions RegistrationOptionsFromPython(
    const py::kwargs& kwargs, py::handle initial_uncertainty, bool map_given) {
  py::dict options = py::dict(kwargs);  // A copy: "preset" is popped.
  const std::string preset = PopPreset(&options);
  RegistrationOptions result =
      preset == "paper" ? PaperRegistrationOptions() : RegistrationOptions();
  if (map_given && options.contains("grid")) {
    ThrowValueError(
        "invalid option: grid does not apply to LayeredMap.register (the map "
        "is built already; give grid options to LayeredMap.build)");
  }
  RegistrationOptionsBinding().Update(options, "", &result);
  if (!initial_uncertainty.is_none()) {
    InitialGuessUncertainty& u = result.initial_uncertainty;
    if (py::isinstance<py::dict>(initial_uncertainty)) {
      InitialGuessUncertaintyBinding().Update(
          initial_uncertainty, "initial_uncertainty.", &u);
    } else {
      std::vector<double> pair;
      if (!OptionCodec<std::vector<double>>::FromPython(initial_uncertainty,
                                                        &pair) ||
          pair.size() != 2) {
        ThrowValueError("invalid option: initial_uncertainty = " +
                        DescribeValue(initial_uncertainty) +
                        "; expected (translation_m, rotation_deg), a dict "
                        "of InitialGuessUncertainty fields, or None");
      }
      u.given = true;
      u.translation_m = pair[0];
      u.rotation_deg = pair[1];
    }
  }
  ValidateOrThrow(RegistrationOptionsBinding(), result);
  return result;
}

LayeredGridOptions LayeredGridOptionsFromPython(const py::kwargs& kwargs) {
  py::dict options = py::dict(kwargs);
  const std::string preset = PopPreset(&options);
  LayeredGridOptions result =
      preset == "paper" ? PaperLayeredGridOptions() : LayeredGridOptions();
  LayeredGridOptionsBinding().Update(options, "", &result);
  ValidateOrThrow(LayeredGridOptionsBinding(), result);
  return result;
}

RangeFilterOptions RangeFilterOptionsFromPython(const py::kwargs& kwargs) {
  RangeFilterOptions result;
  RangeFilterOptionsBinding().Update(kwargs, "", &result);
  ValidateOrThrow(RangeFilterOptionsBinding(), result);
  return result;
}

std::string RegistrationOptionsDoc() {
  return RegistrationOptionsBinding().Describe(RegistrationOptions(), "    ");
}

std::string LayeredGridOptionsDoc() {
  return LayeredGridOptionsBinding().Describe(LayeredGridOptions(), "    ");
}

std::string RangeFilterOptionsDoc() {
  return RangeFilterOptionsBinding().Describe(RangeFilterOptions(), "    ");
}

void DefineOptions(py::module_& m) {
  m.def(
      "default_options",
      [](const std::string& preset) {
        if (preset == "default") {
          return RegistrationOptionsBinding().ToDict(RegistrationOptions());
        }
        if (preset == "paper") {
          return RegistrationOptionsBinding().ToDict(
              PaperRegistrationOptions());
        }
        ThrowValueError("invalid option: preset = '" + preset +
                        "'; expected \"default\" or \"paper\"");
      },
      py::arg("preset") = "default",
      "default_options(preset=\"default\") -> dict\n\n"
      "Every registration option with its value, nested structs as dicts "
      "and enums as their C++ names: RegistrationOptions() for \"default\", "
      "PaperRegistrationOptions() for \"paper\". The dict can be edited and "
      "passed back, e.g. mlndt.register(ref, inp, **options) (its "
      "initial_uncertainty entry then goes to the initial_uncertainty "
      "argument).");
  m.def(
      "resolve_options",
      [](const py::object& initial_uncertainty, const py::kwargs& kwargs) {
        return RegistrationOptionsBinding().ToDict(
            RegistrationOptionsFromPython(kwargs, initial_uncertainty, false));
      },
      py::arg("initial_uncertainty") = py::none(),
      "resolve_options(initial_uncertainty=None, **options) -> dict\n\n"
      "The options mlndt.register would use for these arguments: the "
      "preset with the given\nfields replaced, checked by the library's "
      "IsValid, as default_options() lays them\nout. Raises ValueError "
      "naming an unknown or invalid field, as register does\n(without "
      "reading any cloud): check options before sending work elsewhere.");
}

}  // namespace python
}  // namespace mlndt
