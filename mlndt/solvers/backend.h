#pragma once

// A backend minimises the ML-NDT objective on one layer for one stage of the
// layer schedule: a few iterations on a coarse layer, or iterations until
// convergence on the last one. Every backend minimises the same objective
// (Eq. 10 with the same cells, unmatched-point policy and loss), so that
// benchmarks compare solvers, not models.

#include <memory>
#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/cell_match.h"
#include "mlndt/cost/robust_loss.h"
#include "mlndt/cost/score.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

enum class BackendType {
  CERES,                // Auto-diff residuals in a ceres::Problem per stage.
  NEWTON,               // Hand-written Newton, full Hessian (Sec. 4.1).
  LEVENBERG_MARQUARDT,  // Hand-written LM on whitened residuals (Sec. 4.2).
};

const char* BackendTypeToString(BackendType type);
bool StringToBackendType(std::string value, BackendType* type);

// One iteration of the trace.
struct IterationRecord {
  int layer = 0;           // 1-based layer the iteration ran on.
  int iteration = 0;       // Count over the whole registration, from 1.
  double score = 0.0;      // Objective after the iteration (its layer).
  double step_norm = 0.0;  // ||delta xi|| of the step tried.
  bool step_is_successful = false;
  Vector6d reference_from_input_xi = Vector6d::Zero();
  double time_s = 0.0;  // Wall time since the registration started.
};

struct StageOptions {
  int layer = 1;           // 1-based, for the trace.
  int max_iterations = 3;  // Iterations in this stage. >= 1.
  // > 0: the stage ends with CONVERGENCE once a successful step has
  // ||delta xi|| < step_tolerance (metres and radians mixed, as the paper's
  // update norm). 0: the stage runs max_iterations.
  double step_tolerance = 0.0;
  UnmatchedPolicy unmatched_policy = UnmatchedPolicy::ZERO_RESIDUAL;
  LossType loss = LossType::NONE;
  double loss_scale = 1.0;  // Mahalanobis distance where the loss bends.
  int num_threads = 1;      // Threads for evaluating the objective. >= 1.
  // The stage uses every point_stride-th input point (coarse layers need
  // fewer, layer_scheduler.h). >= 1.
  int point_stride = 1;
  double start_time_s =
      0.0;                  // Registration start (for IterationRecord::time_s).
  int first_iteration = 1;  // Number of the stage's first iteration.
};

struct StageSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  int iterations = 0;
  double final_score = 0.0;
  std::vector<IterationRecord> trace;
};

// The per-point settings of a stage as ScoreOptions.
ScoreOptions ScoreOptionsForStage(const StageOptions& options);

namespace internal {

// Every stride-th point of `points`: `points` itself for stride 1, otherwise
// a copy in *storage. For the backends.
const std::vector<Eigen::Vector3d>& EveryNthPoint(
    const std::vector<Eigen::Vector3d>& points,
    int stride,
    std::vector<Eigen::Vector3d>* storage);

}  // namespace internal

class Backend {
 public:
  virtual ~Backend() = default;
  // Improves *reference_from_input_xi over every options.point_stride-th of
  // `input_points` on `layer`. A registration passes the same input points to
  // every stage of its schedule, so a backend may keep per-point state.
  virtual void SolveStage(const NdtLayer& layer,
                          const std::vector<Eigen::Vector3d>& input_points,
                          const StageOptions& options,
                          Vector6d* reference_from_input_xi,
                          StageSummary* summary) = 0;
};

}  // namespace mlndt
