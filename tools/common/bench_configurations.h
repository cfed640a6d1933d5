#pragma once

// The grid of registration configurations mlndt_bench times: defaults x
// backends x samplings (x GBS cell sizes for gbs) x start layers x losses x
// loss scales x threads, and for the Ceres backend also x minimizers x
// Jacobians x (for the trust-region minimizer) linear solvers x trust
// regions.

#include <ceres/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mlndt/registration/registration_options.h"

namespace mlndt {
namespace tools {

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
  double loss_scale = ObjectiveOptions().loss_scale;
  int threads = 1;

  // The `defaults` with this point's choices; sampling `seed`.
  RegistrationOptions Options(uint64_t seed) const;
};

// The comma-separated list flags that span the grid.
struct BenchGridFlags {
  std::string defaults;        // current, previous
  std::string backends;        // ceres, newton, lm
  std::string samplings;       // gbs, random, all, voxel_centroid
  std::string gbs_cell_sizes;  // [m]
  std::string start_layers;
  std::string linear_solvers;  // Ceres linear solver types.
  std::string trust_regions;   // levenberg_marquardt, dogleg
  std::string minimizers;      // trust_region, bfgs, lbfgs
  std::string jacobians;       // autodiff, analytic
  std::string losses;          // none, huber, cauchy
  std::string loss_scales;     // Mahalanobis distances.
  std::string threads;
  uint64_t seed = 1;
};

// Every configuration of the grid, backends outermost; false with *error
// naming the flag for a bad item or an invalid configuration.
bool ParseBenchConfigurations(const BenchGridFlags& flags,
                              std::vector<BenchConfiguration>* configurations,
                              std::string* error);

// The flag spelling of a Ceres minimizer: trust_region, bfgs, lbfgs.
std::string MinimizerFlagName(const BenchConfiguration& c);

// The flag spelling of a backend: ceres, newton, lm.
std::string BackendFlagName(BackendType type);

// `value` in lower case (enum strings as flags spell them).
std::string LowerCase(std::string value);

}  // namespace tools
}  // namespace mlndt
