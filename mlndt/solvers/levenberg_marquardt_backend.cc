#include "mlndt/solvers/levenberg_marquardt_backend.h"

#include <glog/logging.h>

#include <Eigen/Cholesky>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/solvers/internal/stage_monitor.h"

namespace mlndt {

bool LevenbergMarquardtOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_IN_RANGE(initial_lambda_factor, 1e-15, 1e6);
  MLNDT_OPTION_GT(lambda_decrease, 1.0);
  MLNDT_OPTION_LE(lambda_decrease, 1e6);
  MLNDT_OPTION_GT(lambda_increase, 1.0);
  MLNDT_OPTION_LE(lambda_increase, 1e6);
  return true;
}

void MinimizeLevenbergMarquardt(const Objective& objective,
                                const LevenbergMarquardtOptions& lm_options,
                                const StageControl& control,
                                Vector6d* xi,
                                StageSummary* summary) {
  *summary = StageSummary();
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
