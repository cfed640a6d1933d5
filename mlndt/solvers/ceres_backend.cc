#include "mlndt/solvers/ceres_backend.h"

#include <ceres/iteration_callback.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <glog/logging.h>

#include "mlndt/common/option_table.h"
#include "mlndt/common/thread_budget.h"
#include "mlndt/common/timer.h"
#include "mlndt/cost/layer_binding.h"
#include "mlndt/cost/mlndt_point_cost.h"
#include "mlndt/cost/mlndt_point_cost_analytic.h"
#include "mlndt/solvers/internal/point_evaluation_cache.h"

namespace mlndt {

// One cost function per input point, made on first use, bound to the current
// stage's layer.
class CeresBackend::CostPool {
 public:
  CostPool(const std::vector<Eigen::Vector3d>& points,
           UnmatchedPolicy policy,
           bool analytic)
      : points_(points),
        policy_(policy),
        analytic_(analytic),
        costs_(points.size()) {}

  size_t size() const { return points_.size(); }

  // Binds every cost function to `layer` (until the next Bind).
  void Bind(const NdtLayer& layer) {
    if (binding_ == nullptr) {
      binding_ = std::make_unique<LayerBinding>(layer);
    } else {
      binding_->Rebind(layer);
    }
  }

  ceres::CostFunction* Get(size_t i) {
    if (costs_[i] == nullptr) {
      costs_[i].reset(
          analytic_
              ? static_cast<ceres::CostFunction*>(
                    new MlNdtPointCostAnalytic(*binding_, points_[i], policy_))
              : MlNdtPointCost::Create(*binding_, points_[i], policy_));
    }
    return costs_[i].get();
  }

  // The Problem of every `stride`-th point, built on first use and kept for
  // the later stages with the same stride: its blocks read the layer through
  // the binding, and its one parameter block is `xi()`. Stages with the same
  // stride thus solve the same Problem (same blocks, same order) on another
  // layer, as a freshly built one would. With more than one thread for its
  // blocks (thread_budget.h), a PointEvaluationCache evaluates them in
  // parallel; the results do not change (point_evaluation_cache.h).
  ceres::Problem& ProblemForStride(size_t stride,
                                   const ObjectiveOptions& o,
                                   int max_threads) {
    for (StrideProblem& p : problems_) {
      if (p.stride == stride) return *p.problem;
    }
    StrideProblem p;
    p.stride = stride;
    std::vector<const ceres::CostFunction*> costs;
    for (size_t i = 0; i < size(); i += stride) costs.push_back(Get(i));
    const int threads = ThreadsFor(static_cast<int64_t>(costs.size()),
                                   kMinResidualBlocksPerThread,
                                   max_threads);
    if (threads > 1) {
      p.cache =
          std::make_unique<internal::PointEvaluationCache>(costs, xi_, threads);
      for (size_t j = 0; j < costs.size(); ++j) {
        p.cached_costs.push_back(std::make_unique<internal::CachedPointCost>(
            *p.cache, j, *costs[j]));
      }
    }
    ceres::Problem::Options problem_options;
    // The residual blocks are built here, correctly by construction; the
    // checks cost more than the blocks on small stages.
    problem_options.disable_all_safety_checks = true;
    problem_options.cost_function_ownership =
        ceres::DO_NOT_TAKE_OWNERSHIP;  // The pool's and p's.
    problem_options.evaluation_callback = p.cache.get();
    p.problem = std::make_unique<ceres::Problem>(problem_options);
    // One loss object for every block: the Problem frees it once (if used).
    std::unique_ptr<ceres::LossFunction> loss(CreateLoss(o.loss, o.loss_scale));
    for (size_t j = 0; j < costs.size(); ++j) {
      ceres::CostFunction* cost =
          p.cache != nullptr ? p.cached_costs[j].get() : Get(j * stride);
      p.problem->AddResidualBlock(cost, loss.get(), xi_);
    }
    if (p.problem->NumResidualBlocks() > 0) loss.release();
    problems_.push_back(std::move(p));
    return *problems_.back().problem;
  }

  // The parameter block of every Problem (a stage copies its pose in and
  // out).
  double* xi() { return xi_; }

 private:
  // Destroyed in reverse order: the Problem before the costs and the cache
  // it uses.
  struct StrideProblem {
    size_t stride = 1;
    std::unique_ptr<internal::PointEvaluationCache> cache;  // Or null.
    std::vector<std::unique_ptr<internal::CachedPointCost>> cached_costs;
    std::unique_ptr<ceres::Problem> problem;
  };

  const std::vector<Eigen::Vector3d>& points_;
  const UnmatchedPolicy policy_;
  const bool analytic_;
  std::unique_ptr<LayerBinding> binding_;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs_;
  double xi_[6] = {0, 0, 0, 0, 0, 0};
  // Declared after costs_: destroyed first, before the cost functions.
  std::vector<StrideProblem> problems_;
};

namespace {

// Records the trace and ends the stage as StageControl says.
class TraceCallback : public ceres::IterationCallback {
 public:
  TraceCallback(const StageControl& control,
                const double* xi,
                StageSummary* summary)
      : control_(control), xi_(xi), summary_(summary) {}

  ceres::CallbackReturnType operator()(
      const ceres::IterationSummary& s) override {
    if (s.iteration == 0) return ceres::SOLVER_CONTINUE;  // Initial evaluation.
    IterationRecord record;
    record.score = 2.0 * s.cost;  // Ceres minimises 1/2 sum ||r||^2.
    record.step_norm = s.step_norm;
    record.step_is_successful = s.step_is_successful;
    record.reference_from_input_xi = Eigen::Map<const Vector6d>(xi_);
    record.time_s = NowSeconds() - start_s_;
    summary_->trace.push_back(record);
    end_ = control_.EndAfter(s.step_norm, s.step_is_successful);
    return end_ == StageEnd::NONE ? ceres::SOLVER_CONTINUE
                                  : ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }
  StageEnd end() const { return end_; }

 private:
  const StageControl& control_;
  const double* xi_;
  StageSummary* summary_;
  const double start_s_ = NowSeconds();
  StageEnd end_ = StageEnd::NONE;
};

}  // namespace

const OptionTable& CeresBackendOptionsTable() {
  using S = CeresBackendOptions;
  static const EnumTable linear_solvers =
      EnumTableFromToString(ceres::LinearSolverTypeToString);
  static const EnumTable trust_regions =
      EnumTableFromToString(ceres::TrustRegionStrategyTypeToString);
  static const OptionTable table = OptionTableBuilder<S>("CeresBackendOptions")
                                       .Enum("linear_solver_type",
                                             &S::linear_solver_type,
                                             linear_solvers,
                                             "Ceres linear solver.")
                                       .Enum("trust_region_strategy_type",
                                             &S::trust_region_strategy_type,
                                             trust_regions,
                                             "Ceres trust-region strategy.")
                                       .Validator(&S::IsValid)
                                       .Build();
  return table;
}

bool CeresBackendOptions::IsValid(std::string* error) const {
  if (!CeresBackendOptionsTable().Check(*this, error)) return false;
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = linear_solver_type;
  solver_options.trust_region_strategy_type = trust_region_strategy_type;
  solver_options.minimizer_type = minimizer_type;
  solver_options.line_search_direction_type = line_search_direction_type;
  if (!solver_options.IsValid(error)) {
    *error = "invalid Ceres options: " + *error;
    return false;
  }
  return true;
}

CeresBackend::CeresBackend(const CeresBackendOptions& options)
    : options_(options) {}
CeresBackend::~CeresBackend() = default;

void CeresBackend::SetProblem(const std::vector<Eigen::Vector3d>& input_points,
                              const ObjectiveOptions& objective,
                              int num_threads) {
  objective_ = objective;
  num_threads_ = num_threads;
  pool_ = std::make_unique<CostPool>(
      input_points, objective.unmatched_policy, options_.analytic_jacobians);
}

void CeresBackend::SolveStage(const NdtLayer& layer,
                              const StageControl& control,
                              Vector6d* reference_from_input_xi,
                              StageSummary* summary) {
  *summary = StageSummary();
  CHECK(pool_ != nullptr) << "CeresBackend: SetProblem first";
  CHECK_GE(control.point_stride, 1);
  pool_->Bind(layer);
  ceres::Problem& problem = pool_->ProblemForStride(
      static_cast<size_t>(control.point_stride), objective_, num_threads_);
  double* xi = pool_->xi();
  Eigen::Map<Vector6d> xi_map(xi);
  xi_map = *reference_from_input_xi;

  TraceCallback callback(control, xi, summary);
  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = options_.linear_solver_type;
  solver_options.trust_region_strategy_type =
      options_.trust_region_strategy_type;
  solver_options.minimizer_type = options_.minimizer_type;
  solver_options.line_search_direction_type =
      options_.line_search_direction_type;
  // Ceres' evaluator threads would sum the cost in scheduler-dependent
  // partial sums; the blocks are evaluated in parallel by the Problem's
  // PointEvaluationCache instead, and Ceres sums on one thread.
  solver_options.num_threads = 1;
  solver_options.max_num_iterations = control.max_iterations;
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
  *reference_from_input_xi = xi_map;
  summary->final_score = 2.0 * ceres_summary.final_cost;
  summary->message = ceres_summary.message;
  if (ceres_summary.termination_type == ceres::FAILURE) {
    summary->termination_type = TerminationType::FAILURE;
  } else if (callback.end() != StageEnd::NONE) {
    EndStage(callback.end(), summary);
  } else if (ceres_summary.termination_type == ceres::CONVERGENCE) {
    summary->termination_type = TerminationType::CONVERGENCE;
  } else {
    summary->termination_type = TerminationType::NO_CONVERGENCE;
  }
}

}  // namespace mlndt
