#include "mlndt/schedule/problem_schedule.h"

#include <ceres/iteration_callback.h>
#include <glog/logging.h>

#include <algorithm>

#include "mlndt/common/timer.h"

namespace mlndt {
namespace {

// Ends a stage as its StageControl says (backend.h).
class StageStop : public ceres::IterationCallback {
 public:
  explicit StageStop(const StageControl& control) : control_(control) {}
  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& s) override {
    if (s.iteration > 0 &&
        control_.EndAfter(s.step_norm, s.step_is_successful) !=
            StageEnd::NONE) {
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const StageControl control_;
};

bool CheckInputs(const LayerScheduleOptions& schedule,
                 const ceres::Solver::Options& solver_options,
                 const std::vector<ScheduledBinding>& bindings,
                 std::string* error) {
  if (!schedule.IsValid(error)) {
    *error = "schedule: " + *error;
    return false;
  }
  if (!solver_options.IsValid(error)) {
    *error = "solver_options: " + *error;
    return false;
  }
  if (bindings.empty()) {
    *error = "bindings: none given (nothing to schedule)";
    return false;
  }
  for (size_t b = 0; b < bindings.size(); ++b) {
    const std::string name = "bindings[" + std::to_string(b) + "]";
    if (bindings[b].binding == nullptr || bindings[b].map == nullptr) {
      *error = name + ": null binding or map";
      return false;
    }
    if (bindings[b].map->num_layers() < 1) {
      *error = name + ": the map has no layers";
      return false;
    }
  }
  return true;
}

// Stage k of `num_stages` binds every binding to its stage layer and
// returns those layers.
std::vector<int> BindStage(const LayerScheduleOptions& schedule,
                           const std::vector<ScheduledBinding>& bindings,
                           int k,
                           int num_stages) {
  std::vector<int> layers;
  for (const ScheduledBinding& b : bindings) {
    const int n = b.map->num_layers();
    const int layer =
        std::max(ResolveStartLayer(schedule, n), n - (num_stages - 1 - k));
    b.binding->Rebind(b.map->layer(layer));
    layers.push_back(layer);
  }
  return layers;
}

int NumStages(const LayerScheduleOptions& schedule,
              const std::vector<ScheduledBinding>& bindings) {
  int stages = 1;
  for (const ScheduledBinding& b : bindings) {
    const int n = b.map->num_layers();
    stages = std::max(stages, n - ResolveStartLayer(schedule, n) + 1);
  }
  return stages;
}

void SolveStage(const ceres::Solver::Options& solver_options,
                const LayerScheduleOptions& schedule,
                bool last,
                ceres::Problem* problem,
                ProblemStageSummary* stage) {
  ceres::Solver::Options options = solver_options;
  options.max_num_iterations =
      last ? schedule.max_final_iterations : schedule.iterations_per_layer;
  StageControl control;
  control.step_tolerance =
      last ? schedule.step_tolerance : schedule.coarse_step_tolerance;
  control.end_on_rejected_step =
      !last && schedule.end_coarse_layer_on_rejected_step;
  StageStop stop(control);
  options.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  const double start_s = NowSeconds();
  ceres::Solve(options, problem, &summary);
  stage->time_s = NowSeconds() - start_s;
  stage->iterations = std::max(
      0, summary.num_successful_steps + summary.num_unsuccessful_steps);
  stage->initial_cost = summary.initial_cost;
  stage->final_cost = summary.final_cost;
  stage->ceres_termination = summary.termination_type;
}

}  // namespace

int ProblemScheduleSummary::total_iterations() const {
  int total = 0;
  for (const ProblemStageSummary& stage : stages) total += stage.iterations;
  return total;
}

double ProblemScheduleSummary::total_time_s() const {
  double total = 0.0;
  for (const ProblemStageSummary& stage : stages) total += stage.time_s;
  return total;
}

bool SolveWithLayerSchedule(const LayerScheduleOptions& schedule,
                            const ceres::Solver::Options& solver_options,
                            const std::vector<ScheduledBinding>& bindings,
                            ceres::Problem* problem,
                            ProblemScheduleSummary* summary,
                            std::string* error) {
  CHECK(problem != nullptr);
  CHECK(summary != nullptr);
  CHECK(error != nullptr);
  *summary = ProblemScheduleSummary();
  if (!CheckInputs(schedule, solver_options, bindings, error)) return false;
  const int num_stages = NumStages(schedule, bindings);
  for (int k = 0; k < num_stages; ++k) {
    const bool last = k == num_stages - 1;
    ProblemStageSummary stage;
    stage.layers = BindStage(schedule, bindings, k, num_stages);
    SolveStage(solver_options, schedule, last, problem, &stage);
    summary->stages.push_back(stage);
    if (stage.ceres_termination == ceres::FAILURE) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message = "stage " + std::to_string(k + 1) + " of " +
                         std::to_string(num_stages) + ": Ceres failed";
      BindStage(schedule, bindings, num_stages - 1, num_stages);
      return true;
    }
  }
  const ceres::TerminationType last = summary->stages.back().ceres_termination;
  const bool converged =
      last == ceres::CONVERGENCE || last == ceres::USER_SUCCESS;
  summary->termination_type = converged ? TerminationType::CONVERGENCE
                                        : TerminationType::NO_CONVERGENCE;
  summary->message = converged ? "converged on the finest layers"
                               : "iteration cap reached on the finest layers";
  return true;
}

}  // namespace mlndt
