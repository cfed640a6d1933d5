#include "mlndt/solvers/levenberg_marquardt_backend.h"

#include <glog/logging.h>

#include <Eigen/Cholesky>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/internal/enum_strings.h"
#include "mlndt/solvers/internal/stage_monitor.h"

namespace mlndt {

const char* LmResidualToString(LmResidual residual) {
  switch (residual) {
    case LmResidual::WHITENED:
      return "WHITENED";
    case LmResidual::SCALAR_SCORE:
      return "SCALAR_SCORE";
  }
  return "UNKNOWN";
}

bool StringToLmResidual(std::string value, LmResidual* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(WHITENED, LmResidual);
  MLNDT_STRING_TO_ENUM(SCALAR_SCORE, LmResidual);
  return false;
}

bool LevenbergMarquardtOptions::IsValid(std::string* error) const {
  if (residual != LmResidual::WHITENED &&
      residual != LmResidual::SCALAR_SCORE) {
    if (error) *error = "residual: not a LmResidual value";
    return false;
  }
  MLNDT_OPTION_IN_RANGE(initial_lambda_factor, 1e-15, 1e6);
  MLNDT_OPTION_GT(lambda_decrease, 1.0);
  MLNDT_OPTION_LE(lambda_decrease, 1e6);
  MLNDT_OPTION_GT(lambda_increase, 1.0);
  MLNDT_OPTION_LE(lambda_increase, 1e6);
  return true;
}

namespace {

// The paper's literal LM (Eqs. 18-20): (J^T J + lambda I) delta = -J^T r on
// the scalar residuals r_k = rho(s_k); a step is kept when it lowers the
// score sum_k rho(s_k).
void MinimizeScalarResidualLm(const Objective& objective,
                              const LevenbergMarquardtOptions& lm_options,
                              const StageControl& control,
                              Vector6d* xi,
                              StageSummary* summary) {
  internal::StageMonitor trace(control, summary);
  summary->termination_type = TerminationType::NO_CONVERGENCE;
  summary->message = "iteration cap reached";
  ScalarResidualSystem current;
  if (!objective.EvaluateScalarResiduals(*xi, &current)) {
    summary->termination_type = TerminationType::FAILURE;
    summary->message = "the objective has no scalar residuals";
    return;
  }
  summary->final_score = current.score;
  if (current.matched == 0) {
    summary->termination_type = TerminationType::FAILURE;
    summary->message = "no input point lies in an occupied cell";
    return;
  }
  double lambda =
      lm_options.initial_lambda_factor * current.jtj.diagonal().mean();
  for (int iteration = 0; iteration < control.max_iterations; ++iteration) {
    const Matrix6d damped = current.jtj + lambda * Matrix6d::Identity();
    const Vector6d step = -damped.ldlt().solve(current.jtr);
    if (!step.allFinite()) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message = "the Levenberg-Marquardt step is not finite";
      return;
    }
    const Vector6d candidate_xi = *xi + step;
    ScalarResidualSystem candidate;
    objective.EvaluateScalarResiduals(candidate_xi, &candidate);
    const bool successful =
        candidate.matched > 0 && candidate.score < current.score;
    if (successful) {
      *xi = candidate_xi;
      current = candidate;
      summary->final_score = current.score;
      lambda /= lm_options.lambda_decrease;
    } else {
      lambda *= lm_options.lambda_increase;
    }
    if (trace.Record(current.score, step.norm(), successful, *xi)) {
      summary->termination_type = TerminationType::CONVERGENCE;
      summary->message = "update norm below tolerance";
      return;
    }
  }
}

}  // namespace

void MinimizeLevenbergMarquardt(const Objective& objective,
                                const LevenbergMarquardtOptions& lm_options,
                                const StageControl& control,
                                Vector6d* xi,
                                StageSummary* summary) {
  *summary = StageSummary();
  if (lm_options.residual == LmResidual::SCALAR_SCORE) {
    MinimizeScalarResidualLm(objective, lm_options, control, xi, summary);
    return;
  }
  internal::StageMonitor trace(control, summary);
  summary->termination_type = TerminationType::NO_CONVERGENCE;
  summary->message = "iteration cap reached";
  // The Gauss-Newton Hessian is 2 J^T J and the gradient 2 J^T r, so
  // (H + 2 lambda I) delta = -g is the paper's (J^T J + lambda I) delta = -J^T
  // r.
  ScoreEvaluation current = objective.Evaluate(*xi, HessianType::GAUSS_NEWTON);
  summary->final_score = current.score;
  if (current.matched == 0) {
    summary->termination_type = TerminationType::FAILURE;
    summary->message = "no input point lies in an occupied cell";
    return;
  }
  double lambda = lm_options.initial_lambda_factor *
                  current.hessian.diagonal().mean() / 2.0;
  for (int iteration = 0; iteration < control.max_iterations; ++iteration) {
    const Matrix6d damped =
        current.hessian + 2.0 * lambda * Matrix6d::Identity();
    const Vector6d step = -damped.ldlt().solve(current.gradient);
    if (!step.allFinite()) {
      summary->termination_type = TerminationType::FAILURE;
      summary->message = "the Levenberg-Marquardt step is not finite";
      return;
    }
    const Vector6d candidate_xi = *xi + step;
    const ScoreEvaluation candidate =
        objective.Evaluate(candidate_xi, HessianType::GAUSS_NEWTON);
    const bool successful =
        candidate.matched > 0 && candidate.score < current.score;
    if (successful) {
      *xi = candidate_xi;
      current = candidate;
      summary->final_score = current.score;
      lambda /= lm_options.lambda_decrease;
    } else {
      lambda *= lm_options.lambda_increase;
    }
    if (trace.Record(current.score, step.norm(), successful, *xi)) {
      summary->termination_type = TerminationType::CONVERGENCE;
      summary->message = "update norm below tolerance";
      return;
    }
  }
}

void LevenbergMarquardtBackend::SetProblem(
    const std::vector<Eigen::Vector3d>& input_points,
    const ObjectiveOptions& objective,
    int num_threads) {
  input_points_ = &input_points;
  objective_ = objective;
  num_threads_ = num_threads;
}

void LevenbergMarquardtBackend::SolveStage(const NdtLayer& layer,
                                           const StageControl& control,
                                           Vector6d* reference_from_input_xi,
                                           StageSummary* summary) {
  CHECK(input_points_ != nullptr)
      << "LevenbergMarquardtBackend: SetProblem first";
  std::vector<Eigen::Vector3d> thinned;
  const auto& points =
      internal::EveryNthPoint(*input_points_, control.point_stride, &thinned);
  MinimizeLevenbergMarquardt(
      MlNdtObjective(layer, points, objective_, num_threads_),
      options_,
      control,
      reference_from_input_xi,
      summary);
}

}  // namespace mlndt
