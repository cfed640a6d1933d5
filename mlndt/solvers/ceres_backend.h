#pragma once

// The Ceres backend: each stage solves a ceres::Problem with one auto-diff
// residual block per sampled point (mlndt_point_cost.h; every stride-th point
// on coarse stages) on the stage's layer, for at most the stage's iterations.
// The final stage stops on the update norm through an IterationCallback.
//
// The cost functions outlive the stages: SetProblem makes a pool for the
// registration's points, each cost function is built on first use and reads
// the stage's layer through a LayerBinding (layer_binding.h). The Problems
// outlive them too: one per point stride, built at the first stage with that
// stride and solved again, on another layer, by the later ones (the same
// blocks in the same order, so the same results as a fresh Problem;
// docs/performance.md). So an instance holds state: one per registration,
// not shared between threads.

#include <ceres/types.h>

#include <memory>
#include <string>

#include "mlndt/solvers/backend.h"

namespace mlndt {

class OptionTable;

struct CeresBackendOptions {
  // 6 parameters: dense normal equations are the cheapest adequate solver.
  ceres::LinearSolverType linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  ceres::TrustRegionStrategyType trust_region_strategy_type =
      ceres::LEVENBERG_MARQUARDT;
  // LINE_SEARCH minimises without the linear solver (Ceres' BFGS or LBFGS
  // directions, line_search_direction_type); the trust-region fields then
  // do not apply.
  ceres::MinimizerType minimizer_type = ceres::TRUST_REGION;
  ceres::LineSearchDirectionType line_search_direction_type = ceres::LBFGS;
  // Hand-written Jacobians (mlndt_point_cost_analytic.h) instead of
  // auto-diff of the same residual.
  bool analytic_jacobians = false;

  // Ceres checks the combination (e.g. a sparse solver without a sparse
  // library, DOGLEG with an iterative solver).
  bool IsValid(std::string* error) const;
};

// CeresBackendOptions's fields: name, unit, valid range and help
// (option_table.h).
const OptionTable& CeresBackendOptionsTable();

class CeresBackend : public Backend {
 public:
  explicit CeresBackend(const CeresBackendOptions& options);
  ~CeresBackend() override;
  void SetProblem(const std::vector<Eigen::Vector3d>& input_points,
                  const ObjectiveOptions& objective,
                  int num_threads) override;
  void SolveStage(const NdtLayer& layer,
                  const StageControl& control,
                  Vector6d* reference_from_input_xi,
                  StageSummary* summary) override;

 private:
  class CostPool;

  CeresBackendOptions options_;
  ObjectiveOptions objective_;
  int num_threads_ = 1;
  std::unique_ptr<CostPool> pool_;  // For the points of SetProblem.
};

}  // namespace mlndt
