#include "mlndt/solvers/ceres_backend.h"

#include <ceres/iteration_callback.h>
#include <ceres/solver.h>
#include <glog/logging.h>

#include "mlndt/common/timer.h"
#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/mlndt_point_cost.h"

namespace mlndt {

// One cost function per input point, made on first use, bound to the current
// stage's layer.
class CeresBackend::CostPool {
 public:
  CostPool(const NdtLayer& layer,
           const std::vector<Eigen::Vector3d>& points,
           UnmatchedPolicy policy)
      : binding_(layer),
        points_(points),
        policy_(policy),
        costs_(points.size()) {}

  // True when the pool was made for these points and this policy.
  bool Serves(const std::vector<Eigen::Vector3d>& points,
              UnmatchedPolicy policy) const {
    return policy == policy_ && points == points_;
  }

  void Rebind(const NdtLayer& layer) { binding_.Rebind(layer); }

  ceres::CostFunction* Get(size_t i) {
    if (costs_[i] == nullptr) {
      costs_[i].reset(MlNdtPointCost::Create(binding_, points_[i], policy_));
    }
    return costs_[i].get();
  }

 private:
  LayerBinding binding_;
  const std::vector<Eigen::Vector3d> points_;
  const UnmatchedPolicy policy_;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs_;
};

namespace {

// Records the trace and ends the final stage on a small update norm.
class TraceCallback : public ceres::IterationCallback {
 public:
  TraceCallback(const StageOptions& options,
                const double* xi,
                StageSummary* summary)
      : options_(options), xi_(xi), summary_(summary) {}

  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& s) override {
    if (s.iteration == 0) return ceres::SOLVER_CONTINUE;  // Initial evaluation.
    IterationRecord record;
    record.layer = options_.layer;
    record.iteration =
        options_.first_iteration + static_cast<int>(summary_->trace.size());
    record.score = 2.0 * s.cost;  // Ceres minimises 1/2 sum ||r||^2.
    record.step_norm = s.step_norm;
    record.step_is_successful = s.step_is_successful;
    record.reference_from_input_xi = Eigen::Map<const Vector6d>(xi_);
    record.time_s = NowSeconds() - options_.start_time_s;
    summary_->trace.push_back(record);
    if (options_.step_tolerance > 0.0 && s.step_is_successful &&
        s.step_norm < options_.step_tolerance) {
      converged_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool converged() const { return converged_; }

 private:
  const StageOptions& options_;
  const double* xi_;
  StageSummary* summary_;
  bool converged_ = false;
};

}  // namespace

bool CeresBackendOptions::IsValid(std::string* error) const {
  // Ceres checks the combination (e.g. a sparse solver without a sparse
  // library, DOGLEG with an iterative solver).
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = linear_solver_type;
  solver_options.trust_region_strategy_type = trust_region_strategy_type;
  if (!solver_options.IsValid(error)) {
    *error = "invalid Ceres options: " + *error;
    return false;
  }
  return true;
}

CeresBackend::CeresBackend(const CeresBackendOptions& options)
    : options_(options) {}
CeresBackend::~CeresBackend() = default;

void CeresBackend::SolveStage(const NdtLayer& layer,
                              const std::vector<Eigen::Vector3d>& input_points,
                              const StageOptions& options,
                              Vector6d* reference_from_input_xi,
                              StageSummary* summary) {
  *summary = StageSummary();
  CHECK_GE(options.point_stride, 1);
  if (pool_ == nullptr ||
      !pool_->Serves(input_points, options.unmatched_policy)) {
    pool_ = std::make_unique<CostPool>(
        layer, input_points, options.unmatched_policy);
  }
  pool_->Rebind(layer);

  ceres::Problem::Options problem_options;
  // The residual blocks are built here, correctly by construction; the
  // checks cost more than the blocks on small stages.
  problem_options.disable_all_safety_checks = true;
  problem_options.cost_function_ownership =
      ceres::DO_NOT_TAKE_OWNERSHIP;  // The pool's.
  ceres::Problem problem(problem_options);
  // One loss object for every block: the Problem frees it once (if used).
  std::unique_ptr<ceres::LossFunction> loss(
      CreateLoss(options.loss, options.loss_scale));
  const size_t stride = static_cast<size_t>(options.point_stride);
  for (size_t i = 0; i < input_points.size(); i += stride) {
    problem.AddResidualBlock(
        pool_->Get(i), loss.get(), reference_from_input_xi->data());
  }
  if (problem.NumResidualBlocks() > 0) loss.release();

  TraceCallback callback(options, reference_from_input_xi->data(), summary);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = options_.linear_solver_type;
  solver_options.trust_region_strategy_type =
      options_.trust_region_strategy_type;
  solver_options.num_threads = options.num_threads;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.minimizer_progress_to_stdout = false;
  solver_options.logging_type = ceres::SILENT;
  // Convergence is the update norm (callback); Ceres' own tests stay tight.
  solver_options.function_tolerance = 1e-10;
  solver_options.gradient_tolerance = 1e-12;
  solver_options.parameter_tolerance = 1e-10;
  solver_options.update_state_every_iteration = true;
  solver_options.callbacks.push_back(&callback);

  ceres::Solver::Summary ceres_summary;
  ceres::Solve(solver_options, &problem, &ceres_summary);
  summary->iterations = static_cast<int>(summary->trace.size());
  summary->final_score = 2.0 * ceres_summary.final_cost;
  summary->message = ceres_summary.message;
  if (ceres_summary.termination_type == ceres::FAILURE) {
    summary->termination_type = TerminationType::FAILURE;
  } else if (callback.converged() ||
             ceres_summary.termination_type == ceres::CONVERGENCE) {
    summary->termination_type = TerminationType::CONVERGENCE;
  } else {
    summary->termination_type = TerminationType::NO_CONVERGENCE;
  }
}

}  // namespace mlndt
