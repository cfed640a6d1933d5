#pragma once

// A backend minimises the ML-NDT objective (objective_options.h) on one
// layer for one stage of the layer schedule: a few iterations on a coarse
// layer, or iterations until convergence on the last one. Every backend
// minimises the same objective over the same cells and points, so that
// benchmarks compare solvers, not models.
//
// Use: SetProblem once per registration (the sampled points and the
// objective), then SolveStage once per stage. backend_factory.h makes one.

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "mlndt/cost/objective_options.h"
#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

class EnumTable;
class ResultTable;

enum class BackendType {
  CERES,                // Auto-diff residuals in a ceres::Problem per stage.
  NEWTON,               // Hand-written Newton, full Hessian (Sec. 4.1).
  LEVENBERG_MARQUARDT,  // Hand-written LM on whitened residuals (Sec. 4.2).
};

// The names of BackendType's values (enum_table.h).
const EnumTable& BackendTypeTable();
const char* BackendTypeToString(BackendType type);
// Case-insensitive; "lm" names LEVENBERG_MARQUARDT.
bool StringToBackendType(std::string value, BackendType* type);

// One iteration of the trace. A backend fills score, step and pose, with
// time_s counted from the start of its stage; the layer scheduler sets layer
// and iteration and makes time_s count from the registration's start.
struct IterationRecord {
  int layer = 0;           // 1-based layer the iteration ran on.
  int iteration = 0;       // Count over the whole registration, from 1.
  double score = 0.0;      // Objective after the iteration (its layer).
  double step_norm = 0.0;  // ||delta xi|| of the step tried.
  bool step_is_successful = false;
  Vector6d reference_from_input_xi = Vector6d::Zero();
  double time_s = 0.0;  // Wall time [s]; see above.
};

// IterationRecord's fields: name, unit, help (result_table.h).
const ResultTable& IterationRecordTable();

// Why a stage ended before its iteration cap.
enum class StageEnd {
  NONE,           // It goes on.
  CONVERGED,      // A successful step below step_tolerance.
  LAYER_MINIMUM,  // A rejected step, with end_on_rejected_step or below
                  // rejected_step_tolerance.
};

// How long one stage runs.
struct StageControl {
  int max_iterations = 1;  // Iterations in this stage. >= 1.
  // > 0: the stage ends with CONVERGENCE once a successful step has
  // ||delta xi|| < step_tolerance (metres and radians mixed, as the paper's
  // update norm). A short rejected step does not count: a last layer that
  // keeps rejecting steps ends at its cap, NO_CONVERGENCE (on the Livox
  // sequence counting them let a wrong pose through as CONVERGENCE). 0: the
  // stage runs max_iterations.
  double step_tolerance = 0.0;
  // True: the stage also ends (CONVERGENCE) at its first rejected step. The
  // objective is piecewise smooth (a point changes cell at a cell face); on
  // a coarse layer a rejected step means the layer's minimum is reached at
  // the layer's resolution, and the finer layers go on from there.
  bool end_on_rejected_step = false;
  // > 0: the stage also ends (LAYER_MINIMUM) at a rejected step with
  // ||delta xi|| below this: a step that short is below what the layer
  // resolves, and Ceres' shrinking trust region would only try nearly the
  // same step again (layer_scheduler.h sets it from the cell edge). 0: off.
  double rejected_step_tolerance = 0.0;
  // The stage uses every point_stride-th input point (coarse layers need
  // fewer, layer_scheduler.h). >= 1.
  int point_stride = 1;

  // Whether, and why, an iteration that tried a step of `step_norm` ends
  // the stage.
  StageEnd EndAfter(double step_norm, bool step_is_successful) const;
};

struct StageSummary {
  TerminationType termination_type = TerminationType::FAILURE;
  std::string message;
  double final_score = 0.0;
  std::vector<IterationRecord> trace;  // One record per iteration.
  int iterations() const { return static_cast<int>(trace.size()); }
};

// Sets summary's termination and message for a stage that ended with `end`
// (not NONE): CONVERGENCE.
void EndStage(StageEnd end, StageSummary* summary);

class Backend {
 public:
  virtual ~Backend() = default;
  // Once per registration, before the first stage: the sampled input points
  // (kept by reference: they must outlive every stage), the objective and
  // the threads that evaluate it (>= 1).
  virtual void SetProblem(const std::vector<Eigen::Vector3d>& input_points,
                          const ObjectiveOptions& objective,
                          int num_threads) = 0;
  // Improves *reference_from_input_xi over every control.point_stride-th
  // input point on `layer`.
  virtual void SolveStage(const NdtLayer& layer,
                          const StageControl& control,
                          Vector6d* reference_from_input_xi,
                          StageSummary* summary) = 0;
};

}  // namespace mlndt
