#pragma once

// The Ceres backend: each stage builds a fresh ceres::Problem with one
// auto-diff residual block per sampled point (mlndt_point_cost.h) on the
// stage's layer, and solves it for at most the stage's iterations. The final
// stage stops on the update norm through an IterationCallback.
//
// The cost functions outlive the stages: they are built once per input point
// and read the stage's layer through a LayerBinding (layer_binding.h), so a
// new stage adds existing blocks to a new Problem instead of allocating a
// functor per point (KITTI pair, 14k residuals: building and freeing a
// stage's Problem takes 0.84 ms instead of 3.40 ms; ceres_stage_benchmark).
// So an instance holds state: one per registration, not shared between
// threads; it keeps its functors until destroyed.

#include <ceres/types.h>

#include <memory>
#include <string>

#include "mlndt/solvers/backend.h"

namespace mlndt {

struct CeresBackendOptions {
  // 6 parameters: dense normal equations are the cheapest adequate solver.
  ceres::LinearSolverType linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  ceres::TrustRegionStrategyType trust_region_strategy_type =
      ceres::LEVENBERG_MARQUARDT;

  bool IsValid(std::string* error) const;
};

class CeresBackend : public Backend {
 public:
  explicit CeresBackend(const CeresBackendOptions& options);
  ~CeresBackend() override;
  void SolveStage(const NdtLayer& layer,
                  const std::vector<Eigen::Vector3d>& input_points,
                  const StageOptions& options,
                  Vector6d* reference_from_input_xi,
                  StageSummary* summary) override;

 private:
  class CostPool;

  CeresBackendOptions options_;
  std::unique_ptr<CostPool> pool_;  // For the input points of the last stage.
};

}  // namespace mlndt
