#include "lab/bench/bench_configurations.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {
namespace {

// The choices of every grid axis, parsed.
struct GridAxes {
  std::vector<BenchDefaults> defaults;
  std::vector<BackendType> backends;
  // (method, GBS cell size): one entry per GBS size, one for other methods.
  std::vector<std::pair<SamplingMethod, double>> samplings;
  std::vector<int> start_layers, threads;
  // (minimizer, line-search direction); the direction is unused for
  // TRUST_REGION.
  std::vector<std::pair<ceres::MinimizerType, ceres::LineSearchDirectionType>>
      minimizers;
  std::vector<bool> analytic_jacobians;
  std::vector<LossType> losses;
  std::vector<std::optional<double>> loss_scales;
  std::vector<ceres::LinearSolverType> linear_solvers;
  std::vector<ceres::TrustRegionStrategyType> trust_regions;
};

bool ParseDefaults(const std::vector<std::string>& items,
                   std::vector<BenchDefaults>* defaults,
                   std::string* error) {
  if (items.empty()) {
    *error = "--defaults: expected a comma-separated list of current, previous";
    return false;
  }
  for (const std::string& item : items) {
    if (item == "current") {
      defaults->push_back(BenchDefaults::CURRENT);
    } else if (item == "previous") {
      defaults->push_back(BenchDefaults::PREVIOUS);
    } else {
      *error = "--defaults: '" + item + "' is not current or previous";
      return false;
    }
  }
  return true;
}

bool ParseBackends(const std::vector<std::string>& items,
                   std::vector<BackendType>* backends,
                   std::string* error) {
  if (items.empty()) {
    *error = "--backends: expected a comma-separated list of ceres, newton, lm";
    return false;
  }
  for (const std::string& item : items) {
    BackendType type;
    if (!StringToBackendType(item, &type)) {
      *error = "--backends: '" + item + "' is not ceres, newton or lm";
      return false;
    }
    backends->push_back(type);
  }
  return true;
}

bool ParseSamplings(const BenchGrid& grid,
                    std::vector<std::pair<SamplingMethod, double>>* samplings,
                    std::string* error) {
  const std::vector<std::string>& items = grid.samplings;
  if (items.empty()) {
    *error =
        "--samplings: expected a comma-separated list of gbs, random, all, "
        "voxel_centroid";
    return false;
  }
  std::vector<SamplingMethod> methods;
  for (const std::string& item : items) {
    SamplingMethod method;
    if (!StringToSamplingMethod(item, &method)) {
      *error = "--samplings: '" + item +
               "' is not gbs, random, all or voxel_centroid";
      return false;
    }
    methods.push_back(method);
  }
  const std::vector<double>& gbs_cell_sizes = grid.gbs_cell_sizes;
  if (gbs_cell_sizes.empty()) {
    *error = "--gbs_cell_sizes: expected comma-separated numbers";
    return false;
  }
  for (const SamplingMethod method : methods) {
    if (method != SamplingMethod::GBS) {
      samplings->emplace_back(method, 1.0);
      continue;
    }
    for (const double size : gbs_cell_sizes)
      samplings->emplace_back(method, size);
  }
  return true;
}

// A list of Ceres enum values by their (case-insensitive) names.
template <typename Enum>
bool ParseCeresList(const std::vector<std::string>& items,
                    const std::string& flag,
                    const std::string& expected,
                    bool (*from_string)(std::string, Enum*),
                    std::vector<Enum>* values,
                    std::string* error) {
  if (items.empty()) {
    *error = flag + ": expected a comma-separated list of " + expected;
    return false;
  }
  for (std::string item : items) {
    Enum value;
    UpperCase(&item);
    if (!from_string(item, &value)) {
      *error = flag + ": '" + LowerCase(item) + "' is not " +
               (flag == "--linear_solvers" ? "a Ceres linear solver type"
                                           : "levenberg_marquardt or dogleg");
      return false;
    }
    values->push_back(value);
  }
  return true;
}

bool ParseMinimizers(const std::vector<std::string>& items,
                     GridAxes* axes,
                     std::string* error) {
  if (items.empty()) {
    *error =
        "--minimizers: expected a comma-separated list of trust_region, "
        "bfgs, lbfgs";
    return false;
  }
  for (const std::string& item : items) {
    if (item == "trust_region") {
      axes->minimizers.emplace_back(ceres::TRUST_REGION, ceres::LBFGS);
    } else if (item == "bfgs") {
      axes->minimizers.emplace_back(ceres::LINE_SEARCH, ceres::BFGS);
    } else if (item == "lbfgs") {
      axes->minimizers.emplace_back(ceres::LINE_SEARCH, ceres::LBFGS);
    } else {
      *error =
          "--minimizers: '" + item + "' is not trust_region, bfgs or lbfgs";
      return false;
    }
  }
  return true;
}

// --jacobians, --losses and --loss_scales.
bool ParseObjectiveAxes(const BenchGrid& grid,
                        GridAxes* axes,
                        std::string* error) {
  if (grid.jacobians.empty()) {
    *error =
        "--jacobians: expected a comma-separated list of autodiff, analytic";
    return false;
  }
  for (const std::string& item : grid.jacobians) {
    if (item != "autodiff" && item != "analytic") {
      *error = "--jacobians: '" + item + "' is not autodiff or analytic";
      return false;
    }
    axes->analytic_jacobians.push_back(item == "analytic");
  }
  if (grid.losses.empty()) {
    *error = "--losses: expected a comma-separated list of none, huber, cauchy";
    return false;
  }
  for (const std::string& item : grid.losses) {
    LossType loss;
    if (!StringToLossType(item, &loss)) {
      *error = "--losses: '" + item + "' is not none, huber or cauchy";
      return false;
    }
    axes->losses.push_back(loss);
  }
  // No scale given: each defaults' own (an empty optional).
  axes->loss_scales.assign(grid.loss_scales.begin(), grid.loss_scales.end());
  if (axes->loss_scales.empty()) axes->loss_scales.emplace_back();
  return true;
}

bool ParseAxes(const BenchGrid& grid, GridAxes* axes, std::string* e) {
  if (!ParseMinimizers(grid.minimizers, axes, e) ||
      !ParseObjectiveAxes(grid, axes, e)) {
    return false;
  }
  if (!ParseDefaults(grid.defaults, &axes->defaults, e) ||
      !ParseBackends(grid.backends, &axes->backends, e) ||
      !ParseSamplings(grid, &axes->samplings, e)) {
    return false;
  }
  axes->start_layers = grid.start_layers;
  if (axes->start_layers.empty()) {
    *e = "--start_layers: expected comma-separated integers";
    return false;
  }
  axes->threads = grid.threads;
  if (axes->threads.empty()) {
    *e = "--threads: expected comma-separated integers";
    return false;
  }
  return ParseCeresList<ceres::LinearSolverType>(
             grid.linear_solvers,
             "--linear_solvers",
             "Ceres linear solver types",
             ceres::StringToLinearSolverType,
             &axes->linear_solvers,
             e) &&
         ParseCeresList<ceres::TrustRegionStrategyType>(
             grid.trust_regions,
             "--trust_regions",
             "levenberg_marquardt, dogleg",
             ceres::StringToTrustRegionStrategyType,
             &axes->trust_regions,
             e);
}

// The backend's solver choices: for Ceres every minimizer x Jacobians, the
// trust-region minimizer also x linear solvers x trust regions; one for the
// other backends.
std::vector<BenchConfiguration> SolverChoices(const GridAxes& axes,
                                              BackendType backend) {
  BenchConfiguration c;
  c.backend = backend;
  if (backend != BackendType::CERES) return {c};
  std::vector<BenchConfiguration> choices;
  for (const auto& [minimizer, direction] : axes.minimizers) {
    for (const bool analytic : axes.analytic_jacobians) {
      c.minimizer = minimizer;
      c.line_search_direction = direction;
      c.analytic_jacobians = analytic;
      if (minimizer == ceres::LINE_SEARCH) {
        choices.push_back(c);
        continue;
      }
      for (const auto solver : axes.linear_solvers) {
        for (const auto region : axes.trust_regions) {
          c.linear_solver = solver;
          c.trust_region = region;
          choices.push_back(c);
        }
      }
    }
  }
  return choices;
}

}  // namespace

const char* BenchDefaultsName(BenchDefaults defaults) {
  return defaults == BenchDefaults::CURRENT ? "current" : "previous";
}

RegistrationOptions BenchConfiguration::Options(uint64_t seed) const {
  RegistrationOptions options;
  if (defaults == BenchDefaults::PREVIOUS) {
    options.grid.finest_cell_size_m = 2.0;
    options.grid.coarse_weighting = CoarseWeighting::POINTS;
    options.objective.loss_scale = 3.0;
    options.schedule.step_tolerance = 1e-4;
  }
  options.backend.type = backend;
  options.sampling.method = sampling;
  options.sampling.gbs_cell_size_m = gbs_cell_size_m;
  options.sampling.seed = seed;
  options.schedule.start_layer = start_layer;
  options.backend.ceres.linear_solver_type = linear_solver;
  options.backend.ceres.trust_region_strategy_type = trust_region;
  options.backend.ceres.minimizer_type = minimizer;
  options.backend.ceres.line_search_direction_type = line_search_direction;
  options.backend.ceres.analytic_jacobians = analytic_jacobians;
  options.objective.loss = loss;
  if (loss_scale.has_value()) options.objective.loss_scale = *loss_scale;
  options.num_threads = threads;
  return options;
}

bool ParseBenchConfigurations(const BenchGrid& grid_axes,
                              std::vector<BenchConfiguration>* configurations,
                              std::string* error) {
  GridAxes axes;
  if (!ParseAxes(grid_axes, &axes, error)) return false;
  std::vector<BenchConfiguration> grid;  // With the current defaults.
  for (const BackendType backend : axes.backends) {
    for (const BenchConfiguration& base : SolverChoices(axes, backend)) {
      for (const auto& [sampling, gbs_cell_size] : axes.samplings) {
        for (const int start_layer : axes.start_layers) {
          for (const LossType loss : axes.losses) {
            // A scale means nothing without a loss: one row.
            const size_t num_scales =
                loss == LossType::NONE ? 1 : axes.loss_scales.size();
            for (size_t k = 0; k < num_scales; ++k) {
              for (const int thread_count : axes.threads) {
                BenchConfiguration c = base;
                c.sampling = sampling;
                c.gbs_cell_size_m = gbs_cell_size;
                c.start_layer = start_layer;
                c.loss = loss;
                c.loss_scale =
                    loss == LossType::NONE ? std::nullopt : axes.loss_scales[k];
                c.threads = thread_count;
                if (!c.Options(grid_axes.seed).IsValid(error)) {
                  *error = std::string("invalid configuration (backend ") +
                           BackendFlagName(backend) + ", threads " +
                           std::to_string(thread_count) + "): " + *error;
                  return false;
                }
                grid.push_back(c);
              }
            }
          }
        }
      }
    }
  }
  configurations->clear();
  for (const BenchDefaults defaults : axes.defaults) {
    for (BenchConfiguration c : grid) {
      c.defaults = defaults;
      configurations->push_back(c);
    }
  }
  return true;
}

std::string MinimizerFlagName(const BenchConfiguration& c) {
  if (c.backend != BackendType::CERES) return "";
  if (c.minimizer == ceres::TRUST_REGION) return "trust_region";
  return c.line_search_direction == ceres::BFGS ? "bfgs" : "lbfgs";
}

std::string BackendFlagName(BackendType type) {
  // The library's name in lower case; "lm" is the flags' short spelling.
  return type == BackendType::LEVENBERG_MARQUARDT
             ? "lm"
             : LowerCase(BackendTypeToString(type));
}

std::string LowerCase(std::string value) {
  std::transform(
      value.begin(), value.end(), value.begin(), [](unsigned char c) {
        return static_cast<char>(std::tolower(c));
      });
  return value;
}

}  // namespace mlndt
