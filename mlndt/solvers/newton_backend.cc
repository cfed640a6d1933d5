#include "mlndt/solvers/newton_backend.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"
#include "mlndt/solvers/internal/stage_monitor.h"

namespace mlndt {
namespace {

// H + gamma I with gamma chosen so that the smallest eigenvalue is at least
// `ratio` times the largest (Section 4.1, "safely positive definite").
Matrix6d SafelyPositiveDefinite(const Matrix6d& h, double ratio) {
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(h,
                                                       Eigen::EigenvaluesOnly);
  const double largest =
      std::max(std::abs(solver.eigenvalues().maxCoeff()), 1e-12);
  const double smallest = solver.eigenvalues().minCoeff();
  const double gamma = std::max(0.0, ratio * largest - smallest);
  return h + gamma * Matrix6d::Identity();
}

}  // namespace

const OptionTable& NewtonOptionsTable() {
  using S = NewtonOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("NewtonOptions")
          .Bool("line_search",
                &S::line_search,
                "Backtracking line search (halving the step until the score "
                "decreases).")
          .Int("max_line_search_steps",
               &S::max_line_search_steps,
               Closed(1, 60),
               "Halvings before the step is rejected.")
          .Double("min_eigenvalue_ratio",
                  &S::min_eigenvalue_ratio,
                  "",
                  Closed(1e-15, 1.0),
                  "H is lifted by gamma I until its smallest eigenvalue is "
                  "this fraction of its largest.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool NewtonOptions::IsValid(std::string* error) const {
  return NewtonOptionsTable().Check(*this, error);
}

void MinimizeNewton(const Objective& objective,
                    const NewtonOptions& newton_options,
                    const StageControl& control,
                    Vector6d* xi,
                    StageSummary* summary) {
  internal::StageMonitor trace(control, summary);
  for (int iteration = 0; iteration < control.max_iterations; ++iteration) {
    const ScoreEvaluation current = objective.Evaluate(*xi, HessianType::FULL);
    summary->final_score = current.score;
    if (trace.FailIfUnmatched(current.matched)) return;
    // Eq. (15): xi <- xi - H^-1 g.
    const Matrix6d h = SafelyPositiveDefinite(
        current.hessian, newton_options.min_eigenvalue_ratio);
    const Vector6d step = -h.ldlt().solve(current.gradient);
    if (trace.FailIfNotFinite(step, "Newton")) return;
    double scale = 1.0;
    Vector6d candidate = *xi + step;
    double candidate_score = current.score;
    bool successful = true;
    if (newton_options.line_search) {
      successful = false;
      for (int k = 0; k < newton_options.max_line_search_steps; ++k) {
        if (k > 0) scale *= 0.5;  // The last scale tried is the one recorded.
        candidate = *xi + scale * step;
        candidate_score =
            objective.Evaluate(candidate, HessianType::NONE).score;
        if (candidate_score < current.score) {
          successful = true;
          break;
        }
      }
    } else {
      // The step is taken: the trace records the score it reaches.
      candidate_score = objective.Evaluate(candidate, HessianType::NONE).score;
    }
    if (successful) {
      *xi = candidate;
      summary->final_score = candidate_score;
    }
    const double step_norm = scale * step.norm();
    if (trace.Record(summary->final_score, step_norm, successful, *xi)) {
      return;
    }
    if (!successful) {
      // No decrease along the Newton direction: a (local) minimum.
      summary->termination_type = TerminationType::CONVERGENCE;
      summary->message = "no decrease along the Newton direction";
      return;
    }
  }
}

void NewtonBackend::Minimize(const Objective& objective,
                             const StageControl& control,
                             Vector6d* reference_from_input_xi,
                             StageSummary* summary) const {
  MinimizeNewton(
      objective, options_, control, reference_from_input_xi, summary);
}

}  // namespace mlndt
