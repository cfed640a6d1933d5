#pragma once

// The grid of registration configurations mlndt_bench times: defaults x
// backends x samplings (x GBS cell sizes for gbs) x start layers x losses x
// loss scales x threads, and for the Ceres backend also x minimizers x
// Jacobians x (for the trust-region minimizer) linear solvers x trust
// regions.

#include <ceres/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mlndt/registration/registration_options.h"

namespace mlndt {

// Which defaults a configuration starts from.
enum class BenchDefaults {
  CURRENT,   // RegistrationOptions().
  PREVIOUS,  // The defaults before 1.2 m finest cells, FINEST_CELLS
             // weighting, Cauchy scale 1.5 and a 1e-3 step tolerance: 2 m,
             // POINTS, scale 3, 1e-4.
};

// "current" or "previous".
const char* BenchDefaultsName(BenchDefaults defaults);

// One point of the grid. Ceres-only fields are unused by the other backends.
struct BenchConfiguration {
  BenchDefaults defaults = BenchDefaults::CURRENT;
  BackendType backend = BackendType::CERES;
  SamplingMethod sampling = SamplingMethod::GBS;
  double gbs_cell_size_m = 1.0;
  int start_layer = 1;
  ceres::LinearSolverType linear_solver = ceres::DENSE_NORMAL_CHOLESKY;
  ceres::TrustRegionStrategyType trust_region = ceres::LEVENBERG_MARQUARDT;
  // TRUST_REGION, or LINE_SEARCH with line_search_direction.
  ceres::MinimizerType minimizer = ceres::TRUST_REGION;
  ceres::LineSearchDirectionType line_search_direction = ceres::LBFGS;
  bool analytic_jacobians = false;
  LossType loss = ObjectiveOptions().loss;
  // Empty: the `defaults`' own scale (current 1.5, previous 3).
  std::optional<double> loss_scale;
  int threads = 1;

  // The `defaults` with this point's choices; sampling `seed`.
  RegistrationOptions Options(uint64_t seed) const;
};

// The axes of the grid, one list of items per axis (mlndt_bench splits its
// comma-separated flags of the same names into these). Enum items are
// spelled as the flags spell them.
struct BenchGrid {
  std::vector<std::string> defaults = {"current"};  // current, previous
  std::vector<std::string> backends = {"ceres", "newton", "lm"};
  std::vector<std::string> samplings = {"gbs"};  // gbs, random, all, ...
  std::vector<double> gbs_cell_sizes = {1.0};    // [m], gbs sampling only.
  std::vector<int> start_layers = {LayerScheduleOptions().start_layer};
  // Ceres backend only: linear solver types (dense_normal_cholesky, ...),
  // trust-region strategies (levenberg_marquardt, dogleg), minimizers
  // (trust_region, bfgs, lbfgs) and Jacobians (autodiff, analytic).
  std::vector<std::string> linear_solvers = {"dense_normal_cholesky"};
  std::vector<std::string> trust_regions = {"levenberg_marquardt"};
  std::vector<std::string> minimizers = {"trust_region"};
  std::vector<std::string> jacobians = {"autodiff"};
  std::vector<std::string> losses = {"cauchy"};  // none, huber, cauchy
  // Mahalanobis distances; empty: each defaults' own scale (one row).
  std::vector<double> loss_scales;
  std::vector<int> threads = {1};
  uint64_t seed = 1;  // Sampling seed (random sampling).
};

// Every configuration of the grid, backends outermost; false with *error
// naming the axis (as its flag, "--backends: ...") for a bad item, an empty
// axis or an invalid configuration.
bool ParseBenchConfigurations(const BenchGrid& grid,
                              std::vector<BenchConfiguration>* configurations,
                              std::string* error);

// The flag spelling of a Ceres minimizer: trust_region, bfgs, lbfgs.
std::string MinimizerFlagName(const BenchConfiguration& c);

// The flag spelling of a backend: ceres, newton, lm.
std::string BackendFlagName(BackendType type);

// `value` in lower case (enum strings as flags spell them).
std::string LowerCase(std::string value);

}  // namespace mlndt
