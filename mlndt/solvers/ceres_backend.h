#pragma once

// The Ceres backend: each stage builds a fresh ceres::Problem with one
// auto-diff residual block per sampled point (mlndt_point_cost.h, through the
// public embedding API add_residuals.h) on the stage's layer, and solves it
// for at most the stage's iterations. The final stage stops on the update
// norm through an IterationCallback.

#include <string>

#include <ceres/types.h>

#include "mlndt/solvers/backend.h"

namespace mlndt {

struct CeresBackendOptions {
  // 6 parameters: dense normal equations are the cheapest adequate solver.
  ceres::LinearSolverType linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  ceres::TrustRegionStrategyType trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;

  bool IsValid(std::string* error) const;
};

class CeresBackend : public Backend {
 public:
  explicit CeresBackend(const CeresBackendOptions& options) : options_(options) {}
  void SolveStage(const NdtLayer& layer,
                  const std::vector<Eigen::Vector3d>& input_points,
                  const StageOptions& options,
                  Vector6d* reference_from_input_xi,
                  StageSummary* summary) override;

 private:
  CeresBackendOptions options_;
};

}  // namespace mlndt
