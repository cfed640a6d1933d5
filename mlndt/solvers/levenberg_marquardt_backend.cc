#include "mlndt/solvers/levenberg_marquardt_backend.h"

#include <Eigen/Cholesky>

#include "mlndt/common/enum_table.h"
#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/solvers/internal/stage_monitor.h"

namespace mlndt {

const EnumTable& LmResidualTable() {
  static const EnumTable table({
      {static_cast<int>(LmResidual::WHITENED), "WHITENED"},
      {static_cast<int>(LmResidual::SCALAR_SCORE), "SCALAR_SCORE"},
  });
  return table;
}

const char* LmResidualToString(LmResidual residual) {
  return EnumToString(LmResidualTable(), residual);
}

bool StringToLmResidual(std::string value, LmResidual* residual) {
  return StringToEnum(LmResidualTable(), std::move(value), residual);
}

const OptionTable& LevenbergMarquardtOptionsTable() {
  using S = LevenbergMarquardtOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("LevenbergMarquardtOptions")
          .Double("initial_lambda_factor",
                  &S::initial_lambda_factor,
                  "",
                  Closed(1e-15, 1e6),
                  "lambda_0 / mean(diag(J^T J)).")
          .Double("lambda_decrease",
                  &S::lambda_decrease,
                  "",
                  LeftOpen(1.0, 1e6),
                  "lambda divisor after a successful step.")
          .Double("lambda_increase",
                  &S::lambda_increase,
                  "",
                  LeftOpen(1.0, 1e6),
                  "lambda factor after a rejected step.")
          .Enum("residual",
                &S::residual,
                LmResidualTable(),
                "The residual LM minimises: whitened (3 per point) or "
                "scalar_score (sqrt of the per-point score).")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool LevenbergMarquardtOptions::IsValid(std::string* error) const {
  return LevenbergMarquardtOptionsTable().Check(*this, error);
}

namespace {

// The normal equations of one LM step: (jtj + lambda I) delta = -jtr.
struct LmSystem {
  double score = 0.0;
  size_t matched = 0;
  bool has_normal_equations = false;  // jtj and jtr are set.
  Matrix6d jtj = Matrix6d::Zero();
  Vector6d jtr = Vector6d::Zero();
};

// The whitened form: the Gauss-Newton Hessian is 2 J^T J and the gradient
// 2 J^T r of the 3-vector residuals W e_k, so (H / 2 + lambda I) delta =
// -g / 2 is the paper's (J^T J + lambda I) delta = -J^T r. Without
// `normal_equations` the score alone (the same value): a trial point's
// normal equations are needed only once it is accepted.
bool EvaluateWhitened(const Objective& objective,
                      const Vector6d& xi,
                      bool normal_equations,
                      LmSystem* system) {
  const ScoreEvaluation e = objective.Evaluate(
      xi, normal_equations ? HessianType::GAUSS_NEWTON : HessianType::NONE);
  system->score = e.score;
  system->matched = e.matched;
  system->has_normal_equations = normal_equations;
  system->jtj = e.hessian / 2.0;
  system->jtr = e.gradient / 2.0;
  return true;
}

// The paper's literal form (Eqs. 18-20): the scalar residuals r_k =
// rho(s_k); a step is kept when it lowers the score sum_k rho(s_k). Always
// with the normal equations (its score comes with them).
bool EvaluateScalar(const Objective& objective,
                    const Vector6d& xi,
                    bool /*normal_equations*/,
                    LmSystem* system) {
  ScalarResidualSystem s;
  if (!objective.EvaluateScalarResiduals(xi, &s)) return false;
  system->score = s.score;
  system->matched = s.matched;
  system->has_normal_equations = true;
  system->jtj = s.jtj;
  system->jtr = s.jtr;
  return true;
}

}  // namespace

void MinimizeLevenbergMarquardt(const Objective& objective,
                                const LevenbergMarquardtOptions& lm_options,
                                const StageControl& control,
                                Vector6d* xi,
                                StageSummary* summary) {
  const auto evaluate = lm_options.residual == LmResidual::SCALAR_SCORE
                            ? EvaluateScalar
                            : EvaluateWhitened;
  internal::StageMonitor trace(control, summary);
  LmSystem current;
  if (!evaluate(objective, *xi, /*normal_equations=*/true, &current)) {
    trace.Fail("the objective has no scalar residuals");
    return;
  }
  summary->final_score = current.score;
  if (trace.FailIfUnmatched(current.matched)) return;
  double lambda =
      lm_options.initial_lambda_factor * current.jtj.diagonal().mean();
  bool last_step_taken = true;
  for (int iteration = 0; iteration < control.max_iterations; ++iteration) {
    if (!current.has_normal_equations) {
      evaluate(objective, *xi, /*normal_equations=*/true, &current);
    }
    const Matrix6d damped = current.jtj + lambda * Matrix6d::Identity();
    const Vector6d step = -damped.ldlt().solve(current.jtr);
    if (trace.FailIfNotFinite(step, "Levenberg-Marquardt")) return;
    const Vector6d candidate_xi = *xi + step;
    // The candidate's normal equations with its score when the last step
    // was taken (the next one likely is too), else only once it is taken:
    // a rejected candidate's are never used. The same steps either way.
    LmSystem candidate;
    evaluate(objective, candidate_xi, last_step_taken, &candidate);
    const bool successful =
        candidate.matched > 0 && candidate.score < current.score;
    last_step_taken = successful;
    if (successful) {
      *xi = candidate_xi;
      current = candidate;
      summary->final_score = current.score;
      lambda /= lm_options.lambda_decrease;
    } else {
      lambda *= lm_options.lambda_increase;
    }
    if (trace.Record(current.score, step.norm(), successful, *xi)) return;
  }
}

void LevenbergMarquardtBackend::Minimize(const Objective& objective,
                                         const StageControl& control,
                                         Vector6d* reference_from_input_xi,
                                         StageSummary* summary) const {
  MinimizeLevenbergMarquardt(
      objective, options_, control, reference_from_input_xi, summary);
}

}  // namespace mlndt
